#pragma once
// The live accuracy estimate: the share of a frame's mirror pixels that differ from the exact image,
// estimated from a sample of pixels the reference ray tracer traces alone, with a 95 % interval.
#include <cstddef>
#include <cstdint>

#include "base/Result.h"
#include "reference/ImageMetrics.h"
#include "reference/PixelTracer.h"

namespace specula::reference {

// `hits` of `sampled` with the 95 % Wilson score interval of the share; [0, 1] when nothing was sampled.
struct ShareEstimate {
  std::size_t sampled = 0;
  std::size_t hits = 0;
  double low = 0.0, high = 1.0;
  double share() const { return sampled == 0 ? 0.0 : static_cast<double>(hits) / static_cast<double>(sampled); }
};

ShareEstimate wilsonInterval(std::size_t hits, std::size_t sampled);

inline constexpr int kDefaultAccuracySamples = 256;
inline constexpr int kMaxAccuracySamples = 65536;

struct MismatchSampleOptions {
  int pixels = kDefaultAccuracySamples;  // mirror pixels to compare
  std::uint64_t seed = 0;                // which sample: one per frame
  int threshold = kDefaultMismatchThreshold;
  // Primary rays spent finding mirror pixels, per pixel asked for; a mirror covering less than about
  // 1 / (probesPerPixel · pixels) of the frame may go unsampled.
  int probesPerPixel = 64;
};

struct MismatchSample {
  ShareEstimate mismatch;        // of the sampled mirror pixels, those that mismatch (maskedMismatch's rule)
  std::size_t probedPixels = 0;  // pixels whose primary rays were traced to find the mirror ones
};

// Estimates maskedMismatch(frame, exact image, exact mirror mask).share() without the exact image:
// pixels are taken along a randomly shifted R2 sequence (Roberts 2018), a low-discrepancy, hence
// stratified, walk over the whole frame; those the tracer's primary rays see as mirror (the exact
// mask's rule) are traced in full and compared with the frame's, until `options.pixels` are or the
// probes run out. The frame's own method plays no part in choosing or judging a pixel. Fails when
// the frame's size is not the tracer's or an option is out of range.
Result<MismatchSample> sampleMirrorMismatch(const PixelTracer& truth, const RgbaView& frame,
                                            const MismatchSampleOptions& options);

}  // namespace specula::reference
