#include "bench/ImageComparison.h"

#include <algorithm>
#include <chrono>

#include "reference/PixelTracer.h"

#include "reference/ImageMetrics.h"

namespace specula::bench {

namespace {
// Identical images have infinite PSNR, which neither CSV nor JSON can hold; report this instead.
constexpr double kPsnrCeiling = 100.0;
}  // namespace

Result<ImageComparison> compareWithReference(const render::RenderedFrame& frame,
                                             const reference::ReferenceImage& truth) {
  const reference::RgbaView ours{frame.rgba, frame.width, frame.height}, theirs{truth.rgba, truth.width, truth.height};
  auto psnr = reference::psnr(ours, theirs);
  auto ssim = reference::ssim(ours, theirs);
  auto mismatch = reference::maskedMismatch(ours, theirs, truth.mirrorMask);
  if (!psnr) return Error{psnr.error()};
  if (!ssim) return Error{ssim.error()};
  if (!mismatch) return Error{mismatch.error()};
  return ImageComparison{std::min(*psnr, kPsnrCeiling), *ssim, mismatch->share()};
}

Result<SampledComparison> sampleAgainstReference(const reference::RayTracer& tracer,
                                                 std::shared_ptr<const reference::PosedScene> posed,
                                                 const math::Camera& camera, const render::RenderedFrame& frame,
                                                 std::uint64_t seed) {
  const auto start = std::chrono::steady_clock::now();
  auto pixels = tracer.pixelTracer(std::move(posed), camera, {frame.width, frame.height, 1, 0, frame.samples});
  if (!pixels) return Error{pixels.error()};
  reference::MismatchSampleOptions options;
  options.seed = seed;
  auto sample = reference::sampleMirrorMismatch(**pixels, {frame.rgba, frame.width, frame.height}, options);
  if (!sample) return Error{sample.error()};
  return SampledComparison{*sample,
                           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()};
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

}  // namespace specula::bench
