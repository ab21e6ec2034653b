#pragma once
// `specula bench tessellation`: what each tessellation setting costs (triangles, searches, time)
// and buys (error against the ray-traced reference) on one scene at one pose.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/Result.h"
#include "gl/GlContext.h"
#include "passes/ReflectionSettings.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

namespace specula::bench {

struct TessellationBenchOptions {
  int width = 640, height = 480;
  int frames = 5;     // timed frames per setting, after one warm-up frame
  double time = 0.0;  // scene time of the pose measured
};

struct TessellationBenchRow {
  std::string scene, setting;  // as passes::describeTessellation names it
  passes::TessellationSettings tessellation;
  std::uint32_t triangles = 0;  // virtual triangles drawn (the reflected ones when untessellated)
  std::uint32_t vertices() const { return 3 * triangles; }  // tessellated lists are triangle soups
  std::uint32_t searches = 0;  // reflection searches: scene vertices plus new edge midpoints
  std::uint32_t midpointSearches = 0;
  bool capped = false;                                             // the triangle cap stopped splitting
  double frameMilliseconds = 0.0, tessellationMilliseconds = 0.0;  // medians over the timed frames
  double psnr = 0.0, ssim = 0.0, mirrorMismatch = 0.0;             // against the ray tracer
};

// The sweep the issue asks for: none; full tessellation at levels 1–5; crack-free adaptive with
// the angle metric at 0.1 … 0.001 and the pixel metric at 2, 1, 0.5 px (level 5), plus 0.25 and
// 0.1 px, finer than asked, to find where adaptive reaches full level 4.
std::vector<passes::TessellationSettings> tessellationSweep();

// Virtual triangles the last frame drew: the tessellated ones, or every reflected object's per mirror
// drawn when it was not tessellated.
std::uint32_t virtualTrianglesDrawn(const render::Renderer& renderer, const render::RenderedFrame& frame);

// Measures every setting on `scene`; `progress` hears about each one before it runs.
Result<std::vector<TessellationBenchRow>> benchmarkTessellation(
    gl::GlContext& context, std::shared_ptr<const scene::Scene> scene, const TessellationBenchOptions& options,
    const std::vector<passes::TessellationSettings>& sweep,
    const std::function<void(std::size_t index, const std::string& setting)>& progress);

// The goal, per scene: the adaptive setting with the fewest vertices drawn whose mismatch
// is no worse than full level 4's, if any.
std::optional<TessellationBenchRow> cheapestMatchingFullLevel4(const std::vector<TessellationBenchRow>& rows);

}  // namespace specula::bench
