#include "reference/RayTracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "math/SamplePattern.h"
#include "reference/EmbreeError.h"
#include "reference/PixelTracer.h"
#include "reference/PosedScene.h"

namespace specula::reference {

namespace {

using Clock = std::chrono::steady_clock;

// Larger images are refused rather than risking an allocation that cannot succeed (64 Mpx ≈ 8192²).
constexpr std::size_t kMaxPixels = std::size_t{1} << 26;

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

Result<std::shared_ptr<const PosedScene>> RayTracer::posedScene(const scene::ScenePose& pose) const {
  auto posed = PosedScene::build(device_, *scene_, pose);
  if (!posed) return Error{posed.error()};
  return std::shared_ptr<const PosedScene>(std::move(*posed));
}

Result<std::unique_ptr<PixelTracer>> RayTracer::pixelTracer(std::shared_ptr<const PosedScene> posed,
                                                            const math::Camera& camera,
                                                            const RayTracerOptions& options) const {
  const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
  if (auto problem = math::cameraProblem(camera))
    return Error{*problem + "; fix the scene's camera or camera animation"};
  if (options.width <= 0 || options.height <= 0)
    return Error{"image size " + size + " is empty; pass a width and height of at least 1"};
  const std::size_t pixels = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
  if (pixels > kMaxPixels)
    return Error{"image size " + size + " exceeds " + std::to_string(kMaxPixels) + " pixels; render a smaller image"};
  if (auto problem = math::sampleCountProblem(options.samples)) return Error{*problem};
  if (options.maxBounces < 0)
    return Error{"maxBounces " + std::to_string(options.maxBounces) +
                 " is negative; pass 0 to show mirrors without reflections"};
  return std::make_unique<PixelTracer>(*scene_, std::move(posed), camera, options.width, options.height,
                                       options.samples, options.maxBounces);
}

Result<ReferenceImage> RayTracer::render(const scene::ScenePose& pose, const RayTracerOptions& options) const {
  const Clock::time_point start = Clock::now();
  auto posed = posedScene(pose);
  if (!posed) return Error{"RayTracer::render(): " + posed.error()};
  auto image = render(std::move(*posed), pose.camera, options);
  if (image) image->milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return image;
}

Result<ReferenceImage> RayTracer::render(std::shared_ptr<const PosedScene> posed, const math::Camera& camera,
                                         const RayTracerOptions& options) const {
  const Clock::time_point start = Clock::now();
  auto tracer = pixelTracer(std::move(posed), camera, options);
  if (!tracer) return Error{"RayTracer::render(): " + tracer.error()};

  ReferenceImage image;
  image.width = options.width;
  image.height = options.height;
  const std::size_t pixels = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
  image.rgba.resize(pixels * 4);
  image.mirrorMask.resize(pixels);
  const auto traceRow = [&](int row) {
    for (int column = 0; column < options.width; ++column) {
      const std::size_t pixel =
          static_cast<std::size_t>(row) * static_cast<std::size_t>(options.width) + static_cast<std::size_t>(column);
      const TracedPixel traced = (*tracer)->trace(column, row);
      image.mirrorMask[pixel] = traced.mirror ? 1 : 0;
      std::copy(traced.rgba.begin(), traced.rgba.end(), &image.rgba[4 * pixel]);
    }
  };
  const unsigned threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  forEachRow(options.height, std::min(threads, static_cast<unsigned>(options.height)), traceRow);

  image.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return image;
}

}  // namespace specula::reference
