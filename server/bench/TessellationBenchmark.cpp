#include "bench/TessellationBenchmark.h"

#include <algorithm>

#include "bench/ImageComparison.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"

namespace specula::bench {

namespace {
constexpr int kAdaptiveLevel = 5;

bool isFull(const passes::TessellationSettings& s, int level) {
  return s.mode != passes::TessellationMode::None && s.threshold == 0.0f && s.maxLevel == level;
}
}  // namespace

std::uint32_t virtualTrianglesDrawn(const render::Renderer& renderer, const render::RenderedFrame& frame) {
  if (!frame.tessellation.trianglesPerRound.empty()) return frame.tessellation.finishedTriangles;
  std::size_t triangles = 0;
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    if (std::find(frame.drawnMirrors.begin(), frame.drawnMirrors.end(), mirror.mirrorObject) ==
        frame.drawnMirrors.end())
      continue;
    for (const passes::ReflectionSlotRange& range : mirror.reflected)
      triangles += renderer.scene().meshes[renderer.scene().objects[range.object].mesh].triangleCount();
  }
  return static_cast<std::uint32_t>(triangles);
}

std::vector<passes::TessellationSettings> tessellationSweep() {
  using passes::TessellationMetric;
  using passes::TessellationMode;
  std::vector<passes::TessellationSettings> sweep = {{TessellationMode::None, TessellationMetric::Pixels, 1.0f, 0}};
  for (int level = 1; level <= 5; ++level)
    sweep.push_back({TessellationMode::CrackFree, TessellationMetric::Angle, 0.0f, level});
  for (float threshold : {0.1f, 0.03f, 0.01f, 0.003f, 0.001f})
    sweep.push_back({TessellationMode::CrackFree, TessellationMetric::Angle, threshold, kAdaptiveLevel});
  for (float threshold : {2.0f, 1.0f, 0.5f, 0.25f, 0.1f})
    sweep.push_back({TessellationMode::CrackFree, TessellationMetric::Pixels, threshold, kAdaptiveLevel});
  return sweep;
}

Result<std::vector<TessellationBenchRow>> benchmarkTessellation(
    gl::GlContext& context, std::shared_ptr<const scene::Scene> scene, const TessellationBenchOptions& options,
    const std::vector<passes::TessellationSettings>& sweep,
    const std::function<void(std::size_t index, const std::string& setting)>& progress) {
  const scene::ScenePose pose = scene::ScenePose::at(*scene, options.time);
  auto tracer = reference::RayTracer::create(scene);
  if (!tracer) return Error{tracer.error()};
  auto truth = (*tracer)->render(pose, {options.width, options.height, 1, 0});
  if (!truth) return Error{truth.error()};
  auto renderer = render::Renderer::create(context, scene);
  if (!renderer) return Error{renderer.error()};

  std::vector<TessellationBenchRow> rows;
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    TessellationBenchRow row{scene->name, passes::describeTessellation(sweep[i]), sweep[i]};
    progress(i, row.setting);
    passes::ReflectionSettings settings;
    settings.tessellation = sweep[i];
    // Every mirror searched and nothing ray-cast where virtual objects leave a gap: the sweep is
    // about the tessellation and what its triangles cover.
    settings.rayCast = passes::RayCastRule::Never;
    settings.rayCastUncovered = false;
    std::vector<double> frameTimes, tessellationTimes;
    render::RenderedFrame last;
    for (int frame = 0; frame <= options.frames; ++frame) {  // frame 0 warms up: coherence, buffer sizes
      auto rendered = (*renderer)->render(pose, options.width, options.height, settings);
      if (!rendered) return Error{rendered.error()};
      if (frame > 0) {
        frameTimes.push_back(rendered->timings.totalMilliseconds);
        double tessellation = 0.0;
        for (const render::StageTiming& stage : rendered->timings.stages)
          if (stage.name == "tessellation") tessellation = stage.milliseconds;
        tessellationTimes.push_back(tessellation);
      }
      last = std::move(*rendered);
    }
    row.frameMilliseconds = median(frameTimes);
    row.tessellationMilliseconds = median(tessellationTimes);
    const passes::TessellationStatistics& t = last.tessellation;
    row.triangles = virtualTrianglesDrawn(**renderer, last);
    row.midpointSearches = t.midpointSearches.searched;
    row.searches = last.search.searched + t.midpointSearches.searched;
    row.capped = t.capped;
    auto comparison = compareWithReference(last, *truth);
    if (!comparison) return Error{comparison.error()};
    row.psnr = comparison->psnr;
    row.ssim = comparison->ssim;
    row.mirrorMismatch = comparison->mirrorMismatch;
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<TessellationBenchRow> cheapestMatchingFullLevel4(const std::vector<TessellationBenchRow>& rows) {
  const auto full = std::find_if(rows.begin(), rows.end(), [](const auto& row) { return isFull(row.tessellation, 4); });
  if (full == rows.end()) return std::nullopt;
  std::optional<TessellationBenchRow> best;
  for (const TessellationBenchRow& row : rows) {
    const bool adaptive = row.tessellation.mode != passes::TessellationMode::None && row.tessellation.threshold > 0.0f;
    if (!adaptive || row.mirrorMismatch > full->mirrorMismatch) continue;
    if (!best || row.triangles < best->triangles) best = row;
  }
  return best;
}

}  // namespace specula::bench
