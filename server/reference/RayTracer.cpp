#include "reference/RayTracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <thread>

#include "math/SamplePattern.h"
#include "reference/EnvironmentRadiance.h"
#include "reference/EmbreeError.h"
#include "reference/PosedScene.h"
#include "reference/PrimaryRays.h"
#include "reference/RayOffset.h"
#include "reference/SrgbEncoding.h"
#include "reference/SurfaceShader.h"
#include "reference/TextureSampler.h"

namespace specula::reference {

namespace {

using Clock = std::chrono::steady_clock;

// Larger images are refused rather than risking an allocation that cannot succeed (64 Mpx ≈ 8192²).
constexpr std::size_t kMaxPixels = std::size_t{1} << 26;

// What every ray of one render shares.
struct Tracing {
  const scene::Scene& scene;
  const PosedScene& posed;
  const SurfaceShader& shader;
  int maxBounces;
  float pixelAngle;  // radians a pixel spans on the view axis: the spread of a pixel's ray cone
};

// How far a ray's cone has come: the path length to the ray's origin, and how deep its eye ray goes
// per unit of length (a pixel's footprint grows with the eye ray's depth, as the rasterizer's does).
struct RayCone {
  double travelled = 0.0;
  double eyeDepthPerLength = 1.0;
};

glm::vec3 shadeHit(const Tracing& tracing, const SurfaceHit& hit, const Ray& ray, const RayCone& cone, int bounce);

// Linear colour seen along a reflected ray.
glm::vec3 reflectedColor(const Tracing& tracing, const Ray& ray, const RayCone& cone, int bounce,
                         const Departure* departure) {
  const auto hit = tracing.posed.intersect(ray, kSeenInMirrors, departure);
  return hit ? shadeHit(tracing, *hit, ray, cone, bounce) : environmentRadiance(tracing.scene, ray.direction);
}

// Linear colour of a hit reached after `bounce` reflections.
glm::vec3 shadeHit(const Tracing& tracing, const SurfaceHit& hit, const Ray& ray, const RayCone& cone, int bounce) {
  const scene::SceneObject& object = tracing.scene.objects[hit.object];
  const scene::Material& material = tracing.scene.materials[object.material];
  const double pathLength = cone.travelled + glm::length(hit.position - glm::dvec3(ray.origin));
  const float footprint =
      pixelFootprint(static_cast<float>(pathLength), static_cast<float>(cone.eyeDepthPerLength), tracing.pixelAngle,
                     static_cast<float>(glm::dot(glm::dvec3(ray.direction), hit.geometricNormal)));
  // The viewer is where the ray comes from (the eye, or a mirror point), which decides the lit side.
  const glm::vec3 surface = tracing.shader.shade(material, glm::vec3(hit.position), glm::vec3(hit.shadingNormal),
                                                 hit.uv, footprint * hit.uvPerMetre, ray.origin);
  // Past the last bounce a mirror is an ordinary surface, as a rasterized virtual object of it would be.
  if (!object.mirror || material.reflectivity <= 0.0f || bounce >= tracing.maxBounces) return surface;

  // About the shading normal: exact on analytic surfaces, the rasterizer's interpolated one on meshes.
  const glm::dvec3 incoming(ray.direction), normal = glm::normalize(hit.shadingNormal);
  const glm::dvec3 reflected = glm::normalize(incoming - 2.0 * glm::dot(incoming, normal) * normal);
  // The origin moves off the surface on the side the reflected ray leaves by.
  const glm::dvec3 side = glm::dot(reflected, hit.geometricNormal) >= 0.0 ? hit.geometricNormal : -hit.geometricNormal;
  const Ray next{offsetRayOrigin(glm::vec3(hit.position), glm::vec3(side)), glm::vec3(reflected)};
  std::optional<Departure> departure;
  if (hit.analyticGeometry)
    departure = Departure{*hit.analyticGeometry, {hit.position, glm::dot(incoming, hit.geometricNormal) < 0.0}};
  const glm::vec3 mirrored = reflectedColor(tracing, next, {pathLength, cone.eyeDepthPerLength}, bounce + 1,
                                            departure ? &*departure : nullptr);
  return (1.0f - material.reflectivity) * surface + material.reflectivity * mirrored;
}

// Calls traceRow(row) for every row, on `threads` workers (the calling thread among them) taking rows in turn.
template <class TraceRow>
void forEachRow(int height, unsigned threads, const TraceRow& traceRow) {
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int row = next.fetch_add(1); row < height; row = next.fetch_add(1)) traceRow(row);
  };
  std::vector<std::jthread> workers;
  for (unsigned i = 1; i < threads; ++i) workers.emplace_back(work);
  work();
}

}  // namespace

RayTracer::RayTracer(std::shared_ptr<const scene::Scene> scene, RTCDeviceTy* device)
    : scene_(std::move(scene)), device_(device) {}

RayTracer::~RayTracer() { rtcReleaseDevice(device_); }

Result<std::unique_ptr<RayTracer>> RayTracer::create(std::shared_ptr<const scene::Scene> scene) {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device) return embreeFailure(nullptr, "create a device").value_or(Error{"Embree: cannot create a device"});
  return std::unique_ptr<RayTracer>(new RayTracer(std::move(scene), device));
}

Result<ReferenceImage> RayTracer::render(const scene::ScenePose& pose, const RayTracerOptions& options) const {
  const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
  if (auto problem = math::cameraProblem(pose.camera))
    return Error{"RayTracer::render(): " + *problem + "; fix the scene's camera or camera animation"};
  if (options.width <= 0 || options.height <= 0)
    return Error{"RayTracer::render(): image size " + size + " is empty; pass a width and height of at least 1"};
  const std::size_t pixels = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
  if (pixels > kMaxPixels)
    return Error{"RayTracer::render(): image size " + size + " exceeds " + std::to_string(kMaxPixels) +
                 " pixels; render a smaller image"};
  if (auto problem = math::sampleCountProblem(options.samples)) return Error{"RayTracer::render(): " + *problem};
  if (options.maxBounces < 0)
    return Error{"RayTracer::render(): maxBounces " + std::to_string(options.maxBounces) +
                 " is negative; pass 0 to show mirrors without reflections"};
  const Clock::time_point start = Clock::now();

  auto posed = PosedScene::build(device_, *scene_, pose);
  if (!posed) return Error{"RayTracer::render(): " + posed.error()};
  const SurfaceShader shader(*scene_);
  const PrimaryRays rays(pose.camera, options.width, options.height);
  const auto pixelAngle = static_cast<float>(
      2.0 * std::tan(glm::radians(static_cast<double>(pose.camera.fovYDegrees)) / 2.0) / options.height);
  const Tracing tracing{*scene_, **posed, shader, options.maxBounces, pixelAngle};
  const std::span<const glm::vec2> samples = math::samplePattern(options.samples);

  ReferenceImage image;
  image.width = options.width;
  image.height = options.height;
  image.rgba.resize(pixels * 4);
  image.mirrorMask.resize(pixels);
  const auto traceRow = [&](int row) {
    for (int column = 0; column < options.width; ++column) {
      const std::size_t pixel =
          static_cast<std::size_t>(row) * static_cast<std::size_t>(options.width) + static_cast<std::size_t>(column);
      glm::vec3 sum(0.0f);
      std::size_t mirrorSamples = 0;
      for (const glm::vec2& offset : samples) {
        const glm::dvec3 direction = rays.direction(column, row, offset);
        const Ray primary{rays.origin(), glm::vec3(direction)};
        const auto hit = tracing.posed.intersect(primary, kSeenDirectly, nullptr);
        if (hit && scene_->objects[hit->object].mirror) ++mirrorSamples;
        sum += hit ? shadeHit(tracing, *hit, primary, {0.0, glm::dot(direction, rays.forward())}, 0)
                   : environmentRadiance(*scene_, primary.direction);
      }
      image.mirrorMask[pixel] = 2 * mirrorSamples > samples.size() ? 1 : 0;
      writeSrgb8(sum / static_cast<float>(samples.size()), &image.rgba[4 * pixel]);
    }
  };
  const unsigned threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  forEachRow(options.height, std::min(threads, static_cast<unsigned>(options.height)), traceRow);

  image.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return image;
}

}  // namespace specula::reference
