#pragma once
// A rendered frame against the ray-traced reference, and the median the benchmarks report.
#include <vector>

#include "base/Result.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"

namespace specula::bench {

struct ImageComparison {
  double psnr = 0.0, ssim = 0.0;  // PSNR in dB, at most 100 (identical images)
  double mirrorMismatch = 0.0;    // share of mirror pixels that differ strongly
};

Result<ImageComparison> compareWithReference(const render::RenderedFrame& frame,
                                             const reference::ReferenceImage& truth);

double median(std::vector<double> values);

}  // namespace specula::bench
