#pragma once
// One scene measured the way `specula bench` reports it: per-pass frame times along the scene's own
// animation, search steps warm and cold, reflection-point error against the exact sphere solver,
// and the frame against the ray-traced reference.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/Result.h"
#include "gl/GlContext.h"
#include "math/SamplePattern.h"
#include "reference/MismatchSample.h"
#include "passes/FramePlan.h"
#include "passes/ReflectionSettings.h"
#include "render/FrameTimings.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

namespace specula::bench {

struct BenchOptions {
  int width = 640, height = 480;
  int frames = 60;                              // warm frames along the animation, after a cold one
  double framesPerSecond = 60.0;                // animation time between frames: 1 / framesPerSecond
  int coldWidth = 1280, coldHeight = 720;       // the extra cold-start frame (0 skips it)
  bool reference = true;                        // compare with the ray tracer (CPU; the slowest part)
  int stillSamples = math::kStillFrameSamples;  // the image comparison's anti-aliasing, both sides
  passes::ReflectionSettings reflection;        // defaults but for the plan options (the planner off, for comparison)
  // Per pass by default (the per-pass columns); FrameOnly times whole frames as served, with no
  // wait between passes (on llvmpipe a glFinish after each pass keeps the rasterizer from overlapping them).
  render::PassTiming passTiming = render::PassTiming::PerPass;
};

struct StepStatistics {
  double mean = 0.0;  // 3×3 windows per searched vertex
  unsigned maximum = 0;
  unsigned searched = 0;  // vertices searched in the frames measured
};

struct SceneBenchResult {
  std::string scene;
  std::size_t vertices = 0, triangles = 0, mirrors = 0;
  int width = 0, height = 0, frames = 0;

  double firstFrameMilliseconds = 0.0;            // wall time of the very first frame: shader compilation included
  std::vector<render::StageTiming> stageMedians;  // per pass over the warm frames (0 where a pass did not run)
  double frameMedianMilliseconds = 0.0;           // whole frame, wall clock, median over the warm frames
  double framesPerSecond() const { return frameMedianMilliseconds > 0.0 ? 1000.0 / frameMedianMilliseconds : 0.0; }
  // The last pose drawn with no reflection (`--method none`), median over a few frames: the scene's
  // own raster, a floor that no reflection method on this GL can go below.
  double rasterFloorMilliseconds = 0.0;

  StepStatistics warmSteps;                      // along the animation with frame-to-frame coherence
  StepStatistics coldSteps;                      // the first frame: every vertex from the pyramid
  std::optional<StepStatistics> coldStepsLarge;  // cold at BenchOptions::coldWidth × coldHeight
  unsigned searchedPerFrame = 0, hiddenPerFrame = 0, unsolvedPerFrame = 0;  // the last frame's
  // The last frame's plan: visible mirror parts, those ray-cast, and reflected vertices left out.
  // The planner's last frame measured for it with the method it chose (not an exploration): its
  // rates, and what that frame's methods were predicted to cost and took (RenderedFrame::planner).
  std::optional<render::RenderedFrame::PlannerCosts> planner;
  // Warm frames with every part searched (--ray-cast never) and with every part cast (always), the
  // same poses, the bench's pass timing: median ms each (none when no mirror part was planned).
  std::optional<double> searchedFrameMilliseconds, castFrameMilliseconds;
  std::optional<double> searchedOverCast() const {
    if (!searchedFrameMilliseconds || !castFrameMilliseconds || *castFrameMilliseconds <= 0.0) return std::nullopt;
    return *searchedFrameMilliseconds / *castFrameMilliseconds;
  }
  std::size_t plannedParts = 0, rayCastParts = 0, culledVertices = 0;
  std::size_t belowBudgetVertices = 0;  // last frame: of objects whose image is under the error budget
  std::size_t uncoveredRayCast = 0;     // last frame: pixels no virtual object covered, ray-cast instead
  passes::CastTileCount castTiles;      // last frame, all ray-cast parts: object tiles cast on, of possible

  // Each search strategy over the first frames of the same animation, the cold first frame left out:
  // its search stages' time (the pyramid or ray hierarchy, and the search) and its steps (3×3 windows,
  // or hierarchy nodes). Empty where no part searches.
  struct SearchComparison {
    passes::SearchStrategy strategy = passes::SearchStrategy::Crosshair;
    double milliseconds = 0.0;  // median per frame
    StepStatistics steps;
    std::uint64_t enlarged = 0, inNoCone = 0;  // hierarchy: vertices its cones missed, over the frames
  };
  std::vector<SearchComparison> searches;

  // Reflection-point error in pixels over all frames; absent without an analytic sphere mirror.
  struct PointError {
    std::size_t count = 0;
    double mean = 0.0, p99 = 0.0, maximum = 0.0;
    int misjudgedHidden = 0;   // search hid a vertex whose reflection is visible (grazing)
    int misjudgedVisible = 0;  // search reflected a vertex that has no reflection point
  };
  std::optional<PointError> pointError;

  // The last frame against the ray-traced reference at the same pose; absent when not asked for.
  struct ReferenceComparison {
    double psnr = 0.0, ssim = 0.0;  // PSNR in dB, at most 100 (identical images)
    double mirrorMismatch = 0.0;    // share of mirror pixels that differ strongly
    int samples = 1;                // the images compared took this many samples a pixel (BenchOptions::stillSamples)
    double rayTraceMilliseconds = 0.0;       // one ray a pixel, as the warm frames' one sample
    double stillRayTraceMilliseconds = 0.0;  // `samples` rays a pixel, the image compared
    // What a stream would report for that frame: the live estimate from 256 sampled mirror pixels.
    reference::ShareEstimate mismatchEstimate;
    double estimateMilliseconds = 0.0;
  };
  std::optional<ReferenceComparison> reference;

  // The cost of anti-aliasing: the last pose rendered as a still frame at each of these samples a
  // pixel (the passes run once per sample point), median wall time of a few frames.
  static constexpr int kStillSampleCounts[] = {1, 4, 8};
  struct StillFrame {
    int samples = 1;
    double milliseconds = 0.0;
  };
  std::vector<StillFrame> stillFrames;

  // The parametric meshes' screen-space tessellation at the last pose with the camera moved to
  // kPatchDistanceFactors times its distance from its target: triangles generated, and the area in
  // pixels of those on screen (10th, 50th, 90th percentile). Empty in a scene without patches.
  static constexpr int kPatchDistanceFactors[] = {1, 2, 4};
  struct PatchTessellation {
    int distanceFactor = 1;
    std::size_t triangles = 0;
    double areaP10 = 0.0, areaP50 = 0.0, areaP90 = 0.0;
  };
  std::vector<PatchTessellation> patchTessellation;

  // The frame time as a multiple of the ray tracer's for the same frame (below 1: faster than
  // exact ray tracing on this machine); absent without the reference.
  std::optional<double> timeVersusRayTrace() const {
    if (!reference || reference->rayTraceMilliseconds <= 0.0) return std::nullopt;
    return frameMedianMilliseconds / reference->rayTraceMilliseconds;
  }
};

// Measures `scene` on `context` (which must be current on this thread).
Result<SceneBenchResult> benchmarkScene(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene,
                                        const BenchOptions& options);

}  // namespace specula::bench
