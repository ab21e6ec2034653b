#pragma once
// `specula bench accuracy`: what each step of accuracy costs in time on one scene. Every method and
// setting renders the same camera path; each frame is timed and compared with the ray-traced
// reference of its pose, and the settings no other beats on both time and error form the Pareto front.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/Result.h"
#include "gl/GlContext.h"
#include "passes/ReflectionSettings.h"
#include "scene/Scene.h"

namespace specula::bench {

struct AccuracyBenchOptions {
  int width = 640, height = 480;
  int poses = 8;               // camera path: poses timed and compared per setting, after a warm-up frame
  double orbitDegrees = 12.0;  // the camera swings this far around its target along the path
  double seconds = 0.5;        // scene time the path spans: animated objects move along it
};

// One point of the sweep: a name for people and the settings the renderer gets.
struct AccuracySetting {
  std::string name;    // "adaptive pixels 0.5 px", unique within the sweep
  std::string family;  // "environment map", "search", "adaptive", "full", "G-buffer", "mesh"
  passes::ReflectionSettings settings;
  // Mesh mirrors with an exact shape they only approximate (AnalyticShape::exactSurface false) are
  // re-tessellated as slices × stacks spheres; such a row is compared with the ray tracer of that
  // mesh, and its reflection points with the exact shape's.
  std::optional<glm::ivec2> mirrorMesh{};
};

// The sweep: the environment-map baseline (256 and 1024 px faces), the search without
// tessellation, adaptive pixel (2 … 0.25 px) and angle (0.01 … 0.001) thresholds, full levels 1–4,
// and the G-buffer at half and double resolution and in RGBA16F; on a scene with a mesh mirror
// approximating an exact shape, also that mesh at 32×16 … 256×128. Adaptive, G-buffer and mesh rows
// use the default tessellation otherwise.
std::vector<AccuracySetting> accuracySweep(const scene::Scene& scene);

// `scene` with every mirror whose mesh approximates its exact sphere or ellipsoid given a
// slices × stacks sphere mesh of that shape instead.
scene::Scene withMirrorMeshes(const scene::Scene& scene, glm::ivec2 slicesAndStacks);

struct AccuracyRow {
  std::string scene, setting, family;
  bool reference = false;                               // the ray tracer's own row: error 0 by definition, its time
  double frameMilliseconds = 0.0;                       // median over the path (reference: ray-tracing time)
  double psnr = 0.0, ssim = 0.0, mirrorMismatch = 0.0;  // means over the path against the ray tracer
  // Reflection-point error in pixels over every vertex of the path (search rows on scenes with an
  // analytic sphere mirror; absent otherwise).
  std::optional<double> pointErrorP99{}, pointErrorMax{};
  std::uint64_t reflectionVertices = 0;  // vertices the reflection draws per frame (median over the path)
  std::uint32_t searches = 0;            // reflection searches per frame (median over the path)
  // The live accuracy estimate (reference::sampleMirrorMismatch, the default 256 pixels) of each frame
  // beside the full comparison: its mean, the share of frames whose 95 % interval held the full-frame
  // mismatch, and its median CPU time.
  double estimateMean = 0.0, estimateCoverage = 0.0, estimateMilliseconds = 0.0;
  bool pareto = false;  // no other non-reference row is both faster and more accurate
};

// Renders the camera path once per setting on `scene` and ray-traces each pose once; `progress`
// hears about every step before it runs.
Result<std::vector<AccuracyRow>> benchmarkAccuracy(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene,
                                                   const AccuracyBenchOptions& options,
                                                   const std::vector<AccuracySetting>& sweep,
                                                   const std::function<void(const std::string& step)>& progress);

// Sets `pareto` on every non-reference row that no other non-reference row dominates (time and
// mirror mismatch both no worse, one better).
void markParetoFront(std::vector<AccuracyRow>& rows);

}  // namespace specula::bench
