#pragma once
// A rendered frame against the ray-traced reference, and the median the benchmarks report.
#include <vector>

#include "base/Result.h"
#include "reference/MismatchSample.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"

namespace specula::bench {

struct ImageComparison {
  double psnr = 0.0, ssim = 0.0;  // PSNR in dB, at most 100 (identical images)
  double mirrorMismatch = 0.0;    // share of mirror pixels that differ strongly
};

Result<ImageComparison> compareWithReference(const render::RenderedFrame& frame,
                                             const reference::ReferenceImage& truth);

// The live accuracy estimate of `frame` (reference::sampleMirrorMismatch with its defaults and `seed`),
// traced from `posed`, the geometry of the frame's pose, and the CPU time it took.
struct SampledComparison {
  reference::MismatchSample sample;
  double milliseconds = 0.0;
};
Result<SampledComparison> sampleAgainstReference(const reference::RayTracer& tracer,
                                                 std::shared_ptr<const reference::PosedScene> posed,
                                                 const math::Camera& camera, const render::RenderedFrame& frame,
                                                 std::uint64_t seed);

double median(std::vector<double> values);

}  // namespace specula::bench
