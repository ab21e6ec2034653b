#include "reference/PixelTracer.h"

#include <cmath>
#include <optional>

#include "math/SamplePattern.h"
#include "reference/EnvironmentRadiance.h"
#include "reference/RayOffset.h"
#include "reference/SrgbEncoding.h"
#include "reference/TextureSampler.h"

namespace specula::reference {

namespace {

// What every ray of one pixel tracer shares.
struct Tracing {
  const scene::Scene& scene;
  const PosedScene& posed;
  const SurfaceShader& shader;
  int maxBounces;
  float pixelAngle;
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

}  // namespace

PixelTracer::PixelTracer(const scene::Scene& scene, std::shared_ptr<const PosedScene> posed, const math::Camera& camera,
                         int width, int height, int samples, int maxBounces)
    : scene_(scene),
      posed_(std::move(posed)),
      shader_(scene),
      rays_(camera, width, height),
      width_(width),
      height_(height),
      maxBounces_(maxBounces),
      pixelAngle_(
          static_cast<float>(2.0 * std::tan(glm::radians(static_cast<double>(camera.fovYDegrees)) / 2.0) / height)),
      samples_(math::samplePattern(samples)) {}

TracedPixel PixelTracer::trace(int column, int row) const {
  const Tracing tracing{scene_, *posed_, shader_, maxBounces_, pixelAngle_};
  glm::vec3 sum(0.0f);
  std::size_t mirrorSamples = 0;
  for (const glm::vec2& offset : samples_) {
    const glm::dvec3 direction = rays_.direction(column, row, offset);
    const Ray primary{rays_.origin(), glm::vec3(direction)};
    const auto hit = posed_->intersect(primary, kSeenDirectly, nullptr);
    if (hit && scene_.objects[hit->object].mirror) ++mirrorSamples;
    sum += hit ? shadeHit(tracing, *hit, primary, {0.0, glm::dot(direction, rays_.forward())}, 0)
               : environmentRadiance(scene_, primary.direction);
  }
  TracedPixel pixel;
  pixel.mirror = 2 * mirrorSamples > samples_.size();
  writeSrgb8(sum / static_cast<float>(samples_.size()), pixel.rgba.data());
  return pixel;
}

bool PixelTracer::seesMirror(int column, int row) const {
  std::size_t mirrorSamples = 0;
  for (const glm::vec2& offset : samples_) {
    const Ray primary{rays_.origin(), glm::vec3(rays_.direction(column, row, offset))};
    const auto hit = posed_->intersect(primary, kSeenDirectly, nullptr);
    if (hit && scene_.objects[hit->object].mirror) ++mirrorSamples;
  }
  return 2 * mirrorSamples > samples_.size();
}

}  // namespace specula::reference
