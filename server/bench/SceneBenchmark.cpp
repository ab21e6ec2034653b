#include "bench/SceneBenchmark.h"

#include <algorithm>
#include <chrono>

#include "base/Percentile.h"
#include "bench/ReflectionAccuracy.h"
#include "reference/ImageMetrics.h"
#include "bench/ImageComparison.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"

namespace specula::bench {

namespace {

// Steps of the frames in `search`, summed over frames.
class StepAccumulator {
 public:
  void add(const passes::SearchStatistics& search) {
    searched_ += search.searched;
    steps_ += search.totalSteps;
    maximum_ = std::max(maximum_, search.maxSteps);
  }
  StepStatistics result() const {
    return {searched_ ? static_cast<double>(steps_) / static_cast<double>(searched_) : 0.0, maximum_,
            static_cast<unsigned>(searched_)};
  }

 private:
  std::uint64_t searched_ = 0, steps_ = 0;
  unsigned maximum_ = 0;
};

// Per-stage medians; a stage missing from a frame (no mirror visible) counts as 0 ms there.
std::vector<render::StageTiming> stageMedians(const std::vector<render::FrameTimings>& frames) {
  std::vector<std::string> names;
  for (const render::FrameTimings& frame : frames)
    for (const render::StageTiming& stage : frame.stages)
      if (std::find(names.begin(), names.end(), stage.name) == names.end()) names.push_back(stage.name);
  std::vector<render::StageTiming> medians;
  for (const std::string& name : names) {
    std::vector<double> values;
    for (const render::FrameTimings& frame : frames) {
      const auto stage =
          std::find_if(frame.stages.begin(), frame.stages.end(), [&](const auto& s) { return s.name == name; });
      values.push_back(stage == frame.stages.end() ? 0.0 : stage->milliseconds);
    }
    medians.push_back({name, median(std::move(values))});
  }
  return medians;
}

// `pose` as a still frame (BenchOptions::stillSamples) against the ray tracer at the same samples,
// and the ray tracer's time at one ray a pixel, what the warm frames' time is set against.
Result<SceneBenchResult::ReferenceComparison> compareWithRayTracer(std::shared_ptr<const scene::Scene> scene,
                                                                   render::Renderer& renderer,
                                                                   const scene::ScenePose& pose,
                                                                   const BenchOptions& options) {
  auto still = renderer.render(pose, options.width, options.height, options.reflection, options.stillSamples);
  if (!still) return Error{still.error()};
  auto tracer = reference::RayTracer::create(std::move(scene));
  if (!tracer) return Error{tracer.error()};
  reference::RayTracerOptions traced;
  traced.width = options.width;
  traced.height = options.height;
  auto single = (*tracer)->render(pose, traced);
  if (!single) return Error{single.error()};
  traced.samples = options.stillSamples;
  auto truth = options.stillSamples == 1 ? std::move(single) : (*tracer)->render(pose, traced);
  if (!truth) return Error{truth.error()};
  auto comparison = bench::compareWithReference(*still, *truth);
  if (!comparison) return Error{comparison.error()};
  // The ray-trace times above include building the hierarchy, as a reference image's do; the estimate builds its own.
  auto posed = (*tracer)->posedScene(pose);
  if (!posed) return Error{posed.error()};
  auto estimate = sampleAgainstReference(**tracer, std::move(*posed), pose.camera, *still, 0);
  if (!estimate) return Error{"the live estimate: " + estimate.error()};
  return SceneBenchResult::ReferenceComparison{comparison->psnr,
                                               comparison->ssim,
                                               comparison->mirrorMismatch,
                                               options.stillSamples,
                                               options.stillSamples == 1 ? truth->milliseconds : single->milliseconds,
                                               truth->milliseconds,
                                               estimate->sample.mismatch,
                                               estimate->milliseconds};
}

// The last pose as a still frame at each of kStillSampleCounts, median over a few frames.
Result<std::vector<SceneBenchResult::StillFrame>> stillFrames(render::Renderer& renderer, const scene::ScenePose& pose,
                                                              const BenchOptions& options) {
  constexpr int kStillFrames = 3;
  std::vector<SceneBenchResult::StillFrame> rows;
  for (const int samples : SceneBenchResult::kStillSampleCounts) {
    std::vector<double> totals;
    for (int frame = 0; frame < kStillFrames; ++frame) {
      auto rendered = renderer.render(pose, options.width, options.height, options.reflection, samples);
      if (!rendered) return Error{rendered.error()};
      totals.push_back(rendered->timings.totalMilliseconds);
    }
    rows.push_back({samples, median(std::move(totals))});
  }
  return rows;
}

// Frames each search strategy is timed on, after the cold one.
constexpr int kSearchComparisonFrames = 10;

// Every search strategy (the explosion map's look-ups unrefined) along the scene's first frames
// (coherence from the first, cold, one), on every mirror's mesh, extrusions included.
Result<std::vector<SceneBenchResult::SearchComparison>> compareSearches(render::Renderer& renderer,
                                                                        const BenchOptions& options) {
  std::vector<SceneBenchResult::SearchComparison> comparisons;
  for (passes::SearchStrategy strategy : passes::kSearchStrategies) {
    passes::ReflectionSettings settings = options.reflection;
    settings.search = strategy;
    settings.explosionRefine = false;
    settings.rayCast = passes::RayCastRule::Never;  // every visible mirror part searched, so both searches are compared
    settings.solveExtrusions = false;               // an extrusion's mesh is searched too, not solved
    renderer.resetCoherence();
    SceneBenchResult::SearchComparison comparison{strategy, 0.0, {}, 0, 0};
    StepAccumulator steps;
    std::vector<double> milliseconds;
    for (int frame = 0; frame <= kSearchComparisonFrames; ++frame) {
      auto rendered = renderer.render(scene::ScenePose::at(renderer.scene(), frame / options.framesPerSecond),
                                      options.width, options.height, settings);
      if (!rendered) return Error{rendered.error()};
      if (frame == 0 || rendered->search.searched == 0) continue;
      steps.add(rendered->search);
      comparison.enlarged += rendered->search.enlarged;
      comparison.inNoCone += rendered->search.inNoCone;
      double searchStages = 0.0;
      for (const render::StageTiming& stage : rendered->timings.stages)
        if (stage.name == "gbuffer-pyramid" || stage.name == "ray-hierarchy" || stage.name == "explosion-map" ||
            stage.name == "search")
          searchStages += stage.milliseconds;
      milliseconds.push_back(searchStages);
    }
    if (milliseconds.empty()) return std::vector<SceneBenchResult::SearchComparison>{};
    comparison.milliseconds = median(std::move(milliseconds));
    comparison.steps = steps.result();
    comparisons.push_back(comparison);
  }
  renderer.resetCoherence();
  return comparisons;
}

// Median frame times along the animation's first frames with every mirror part searched and with
// every part cast, each after a cold frame: what the planner chooses between.
Status compareMethods(render::Renderer& renderer, const BenchOptions& options, SceneBenchResult& result) {
  constexpr int kMethodComparisonFrames = 10;
  for (passes::RayCastRule rule : {passes::RayCastRule::Never, passes::RayCastRule::Always}) {
    passes::ReflectionSettings settings = options.reflection;
    settings.rayCast = rule;
    renderer.resetCoherence();
    std::vector<double> totals;
    bool planned = false;
    for (int frame = 0; frame <= kMethodComparisonFrames; ++frame) {
      auto rendered = renderer.render(scene::ScenePose::at(renderer.scene(), frame / options.framesPerSecond),
                                      options.width, options.height, settings);
      if (!rendered) return Error{rendered.error()};
      planned = planned || !rendered->plan.empty();
      if (frame > 0) totals.push_back(rendered->timings.totalMilliseconds);
    }
    if (!planned) return {};
    (rule == passes::RayCastRule::Never ? result.searchedFrameMilliseconds : result.castFrameMilliseconds) =
        median(std::move(totals));
  }
  renderer.resetCoherence();
  return {};
}

// Median wall time of the pose drawn without reflections, after one frame to settle the targets.
double rasterFloor(render::Renderer& renderer, const scene::ScenePose& pose, const BenchOptions& options) {
  constexpr int kFloorFrames = 10;
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::None;
  std::vector<double> totals;
  for (int frame = 0; frame <= kFloorFrames; ++frame) {
    auto rendered = renderer.render(pose, options.width, options.height, settings);
    if (rendered && frame > 0) totals.push_back(rendered->timings.totalMilliseconds);
  }
  return totals.empty() ? 0.0 : median(std::move(totals));
}

// The tessellation of the scene's patches at `pose` from farther and farther along the line of sight.
Result<std::vector<SceneBenchResult::PatchTessellation>> patchTessellation(render::Renderer& renderer,
                                                                           scene::ScenePose pose,
                                                                           const BenchOptions& options) {
  std::vector<SceneBenchResult::PatchTessellation> rows;
  const math::Camera camera = pose.camera;
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::None;  // only the view matters
  for (const int factor : SceneBenchResult::kPatchDistanceFactors) {
    pose.camera.eye = camera.target + static_cast<float>(factor) * (camera.eye - camera.target);
    auto frame = renderer.render(pose, options.width, options.height, settings);
    if (!frame) return Error{frame.error()};
    auto measure = renderer.measurePatchTessellation(pose, *frame);
    if (!measure) return Error{measure.error()};
    if (measure->patches == 0) return rows;
    const std::vector<double> areas(measure->pixelAreas.begin(), measure->pixelAreas.end());
    rows.push_back({factor, measure->triangles, nearestRankPercentile(areas, 0.1), nearestRankPercentile(areas, 0.5),
                    nearestRankPercentile(areas, 0.9)});
  }
  return rows;
}

}  // namespace

Result<SceneBenchResult> benchmarkScene(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene,
                                        const BenchOptions& options) {
  SceneBenchResult result;
  result.scene = scene->name;
  result.vertices = scene->vertexCount();
  result.triangles = scene->triangleCount();
  result.mirrors = scene->mirrorCount();
  result.width = options.width;
  result.height = options.height;
  result.frames = options.frames;

  const auto started = std::chrono::steady_clock::now();
  auto renderer = render::Renderer::create(context, scene);
  if (!renderer) return Error{renderer.error()};
  render::Renderer& r = **renderer;
  r.setPassTiming(options.passTiming);
  const auto poseAt = [&](int frame) { return scene::ScenePose::at(*scene, frame / options.framesPerSecond); };

  // Frame 0 is cold: every vertex climbs the pyramid. Its wall time includes shader compilation.
  const passes::ReflectionSettings& settings = options.reflection;
  scene::ScenePose pose = poseAt(0);
  auto cold = r.render(pose, options.width, options.height, settings);
  if (!cold) return Error{cold.error()};
  result.firstFrameMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  StepAccumulator coldSteps;
  coldSteps.add(cold->search);
  result.coldSteps = coldSteps.result();

  const bool measurePoints = hasExactMirror(*scene);
  ReflectionPointErrors pointErrors;
  const auto addPointErrors = [&](const render::RenderedFrame& frame) {
    if (!measurePoints || frame.search.searched == 0) return;  // nothing searched: every mirror ray-cast
    ReflectionPointErrors errors = measureReflectionPoints(r, pose, frame);
    pointErrors.pixels.insert(pointErrors.pixels.end(), errors.pixels.begin(), errors.pixels.end());
    pointErrors.searchHiddenButExactVisible += errors.searchHiddenButExactVisible;
    pointErrors.exactHiddenButSearchVisible += errors.exactHiddenButSearchVisible;
  };
  addPointErrors(*cold);

  StepAccumulator warmSteps;
  std::vector<render::FrameTimings> timings;
  std::vector<double> totals;
  render::RenderedFrame last = std::move(*cold);
  for (int frame = 1; frame <= options.frames; ++frame) {
    pose = poseAt(frame);
    auto rendered = r.render(pose, options.width, options.height, settings);
    if (!rendered) return Error{rendered.error()};
    warmSteps.add(rendered->search);
    timings.push_back(rendered->timings);
    totals.push_back(rendered->timings.totalMilliseconds);
    addPointErrors(*rendered);
    if (rendered->planner.measured && !rendered->planner.explored) result.planner = rendered->planner;
    last = std::move(*rendered);
  }
  result.warmSteps = warmSteps.result();
  result.stageMedians = stageMedians(timings);
  result.frameMedianMilliseconds = median(totals);
  result.searchedPerFrame = last.search.searched;
  result.hiddenPerFrame = last.search.hidden;
  result.unsolvedPerFrame = last.search.unsolved;
  result.plannedParts = last.plan.size();
  for (const render::MirrorPlanSummary& part : last.plan) {
    result.rayCastParts += part.method == passes::PartMethod::RayCast ? 1 : 0;
    result.culledVertices += part.culledVertices;
    result.belowBudgetVertices += part.belowBudgetVertices;
    result.uncoveredRayCast += part.uncoveredRayCast;
    result.castTiles.listed += part.castTiles.listed;
    result.castTiles.possible += part.castTiles.possible;
  }
  if (measurePoints && !pointErrors.pixels.empty()) {  // none where every mirror was ray-cast
    result.pointError = SceneBenchResult::PointError{pointErrors.pixels.size(),
                                                     pointErrors.mean(),
                                                     pointErrors.percentile(0.99),
                                                     pointErrors.percentile(1.0),
                                                     pointErrors.searchHiddenButExactVisible,
                                                     pointErrors.exactHiddenButSearchVisible};
  }

  // Right after the warm frames, so the still frame's searches start where the animation left them.
  if (options.reference) {
    auto comparison = compareWithRayTracer(scene, r, pose, options);
    if (!comparison) return Error{"ray-traced reference for " + scene->name + ": " + comparison.error()};
    result.reference = *comparison;
  }
  result.rasterFloorMilliseconds = rasterFloor(r, pose, options);
  auto still = stillFrames(r, pose, options);
  if (!still) return Error{still.error()};
  result.stillFrames = std::move(*still);
  auto tessellation = patchTessellation(r, pose, options);
  if (!tessellation) return Error{tessellation.error()};
  result.patchTessellation = std::move(*tessellation);
  auto searches = compareSearches(r, options);
  if (!searches) return Error{searches.error()};
  result.searches = std::move(*searches);
  if (Status status = compareMethods(r, options, result); !status) return Error{status.error()};

  if (options.coldWidth > 0 && options.coldHeight > 0) {
    passes::ReflectionSettings coldStart = settings;
    coldStart.coherence = false;
    auto large = r.render(pose, options.coldWidth, options.coldHeight, coldStart);
    if (!large) return Error{large.error()};
    StepAccumulator largeSteps;
    largeSteps.add(large->search);
    result.coldStepsLarge = largeSteps.result();
  }
  return result;
}

}  // namespace specula::bench
