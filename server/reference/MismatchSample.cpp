#include "reference/MismatchSample.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace specula::reference {

namespace {

// Two-sided 95 %: the standard normal's 0.975 quantile.
constexpr double kZ95 = 1.959963984540054;

// The R2 sequence's steps: 1 / g and 1 / g², g the plastic number (the real root of x³ = x + 1).
constexpr double kPlastic = 1.324717957244746;
constexpr double kStepX = 1.0 / kPlastic, kStepY = 1.0 / (kPlastic * kPlastic);

}  // namespace

ShareEstimate wilsonInterval(std::size_t hits, std::size_t sampled) {
  ShareEstimate estimate{sampled, hits, 0.0, 1.0};
  if (sampled == 0) return estimate;
  const double n = static_cast<double>(sampled), p = estimate.share(), z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = kZ95 / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  // At 0 or n hits the exact bound is 0 or 1; rounding must not leave the interval short of it.
  estimate.low = hits == 0 ? 0.0 : std::max(0.0, centre - half);
  estimate.high = hits == sampled ? 1.0 : std::min(1.0, centre + half);
  return estimate;
}

Result<MismatchSample> sampleMirrorMismatch(const PixelTracer& truth, const RgbaView& frame,
                                            const MismatchSampleOptions& options) {
  if (frame.width != truth.width() || frame.height != truth.height())
    return Error{"sampleMirrorMismatch(): the frame is " + std::to_string(frame.width) + "x" +
                 std::to_string(frame.height) + " but the tracer's view is " + std::to_string(truth.width()) + "x" +
                 std::to_string(truth.height()) + "; trace the frame's own size"};
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height);
  if (frame.rgba.size() != 4 * pixels)
    return Error{"sampleMirrorMismatch(): the frame holds " + std::to_string(frame.rgba.size()) +
                 " bytes, not 4 a pixel"};
  if (options.pixels < 1 || options.pixels > kMaxAccuracySamples)
    return Error{"sampleMirrorMismatch(): " + std::to_string(options.pixels) + " sample pixels; pass 1 to " +
                 std::to_string(kMaxAccuracySamples)};
  if (options.probesPerPixel < 1) return Error{"sampleMirrorMismatch(): probesPerPixel must be at least 1"};

  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double shiftX = unit(random), shiftY = unit(random);
  const std::size_t probes =
      std::min(pixels, static_cast<std::size_t>(options.pixels) * static_cast<std::size_t>(options.probesPerPixel));
  std::vector<bool> visited(pixels, false);
  MismatchSample sample;
  std::size_t sampled = 0, mismatched = 0;
  // The sequence may land on a pixel twice; it walks on until it has probed `probes` distinct pixels.
  for (std::uint64_t i = 0;
       sample.probedPixels < probes && sampled < static_cast<std::size_t>(options.pixels) && i < 4 * probes + 64; ++i) {
    const double x = std::fmod(shiftX + static_cast<double>(i) * kStepX, 1.0);
    const double y = std::fmod(shiftY + static_cast<double>(i) * kStepY, 1.0);
    const int column = std::min(frame.width - 1, static_cast<int>(x * frame.width));
    const int row = std::min(frame.height - 1, static_cast<int>(y * frame.height));
    const std::size_t index =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(column);
    if (visited[index]) continue;
    visited[index] = true;
    ++sample.probedPixels;
    if (!truth.seesMirror(column, row)) continue;
    const TracedPixel exact = truth.trace(column, row);
    ++sampled;
    if (pixelsMismatch(&frame.rgba[4 * index], exact.rgba.data(), options.threshold)) ++mismatched;
  }
  sample.mismatch = wilsonInterval(mismatched, sampled);
  return sample;
}

}  // namespace specula::reference
