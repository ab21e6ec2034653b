#include "bench/AccuracyBenchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "bench/ImageComparison.h"
#include "bench/ReflectionAccuracy.h"
#include "bench/TessellationBenchmark.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/Primitives.h"
#include "scene/ScenePose.h"

namespace specula::bench {

namespace {

using passes::ReflectionMethod;
using passes::TessellationMetric;
using passes::TessellationMode;

AccuracySetting withTessellation(std::string name, std::string family, passes::TessellationSettings tessellation) {
  AccuracySetting setting{std::move(name), std::move(family), {}};
  setting.settings.tessellation = tessellation;
  return setting;
}

// Pose `index` of the path: the scene's animation at its share of `seconds`, the camera swung
// about its up axis through the target by its share of the orbit (centred on the scene's camera).
scene::ScenePose pathPose(const scene::Scene& scene, const AccuracyBenchOptions& options, int index) {
  const double share = options.poses > 1 ? static_cast<double>(index) / (options.poses - 1) : 0.5;
  scene::ScenePose pose = scene::ScenePose::at(scene, share * options.seconds);
  math::Camera& camera = pose.camera;
  const float angle = static_cast<float>(glm::radians((share - 0.5) * options.orbitDegrees));
  const glm::mat4 swing = glm::rotate(glm::mat4(1.0f), angle, glm::normalize(camera.up));
  camera.eye = camera.target + glm::vec3(swing * glm::vec4(camera.eye - camera.target, 0.0f));
  return pose;
}

// Triangles the reflection draws: the virtual ones, or the reflected objects into six cube faces.
std::uint64_t reflectionTriangles(const render::Renderer& renderer, const render::RenderedFrame& frame,
                                  ReflectionMethod method) {
  if (method == ReflectionMethod::Search) return virtualTrianglesDrawn(renderer, frame);
  if (method != ReflectionMethod::EnvironmentMap) return 0;
  constexpr std::uint64_t kCubeFaces = 6;
  return kCubeFaces * virtualTrianglesDrawn(renderer, frame);  // untessellated: each reflected triangle once per face
}

std::uint64_t medianOf(std::vector<std::uint64_t> values) {
  std::vector<double> asDouble(values.begin(), values.end());
  return static_cast<std::uint64_t>(median(std::move(asDouble)));
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double value : values) sum += value;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

}  // namespace

bool approximatesAnExactShape(const scene::SceneObject& object) {
  return object.mirror && object.mirror->analytic && !object.mirror->analytic->exactSurface;
}

scene::Scene withMirrorMeshes(const scene::Scene& scene, glm::ivec2 slicesAndStacks) {
  scene::Scene result = scene;
  for (scene::SceneObject& object : result.objects) {
    if (!approximatesAnExactShape(object)) continue;
    const scene::AnalyticShape& shape = *object.mirror->analytic;
    scene::Mesh mesh =
        scene::primitives::uvSphere(scene.meshes[object.mesh].name, 1.0f, slicesAndStacks.x, slicesAndStacks.y);
    // The unit sphere onto the shape in object space: positions by centre + radii, normals by 1 / radii.
    for (scene::Vertex& v : mesh.vertices) {
      v.position = shape.center + v.position * shape.radii;
      v.normal = glm::normalize(v.normal / shape.radii);
    }
    object.mesh = static_cast<std::uint32_t>(result.meshes.size());
    result.meshes.push_back(std::move(mesh));
  }
  return result;
}

std::vector<AccuracySetting> accuracySweep(const scene::Scene& scene) {
  std::vector<AccuracySetting> sweep;
  for (int faceSize : {256, 1024}) {
    AccuracySetting setting{"environment map " + std::to_string(faceSize) + " px", "environment map", {}};
    setting.settings.method = ReflectionMethod::EnvironmentMap;
    setting.settings.environmentMapSize = faceSize;
    sweep.push_back(setting);
  }
  sweep.push_back(withTessellation("search, no tessellation", "search",
                                   {TessellationMode::None, TessellationMetric::Pixels, 1.0f, 0}));
  for (float pixels : {2.0f, 1.0f, 0.5f, 0.25f}) {
    char name[64];
    std::snprintf(name, sizeof name, "adaptive %g px", pixels);
    sweep.push_back(
        withTessellation(name, "adaptive", {TessellationMode::CrackFree, TessellationMetric::Pixels, pixels, 4}));
  }
  for (float angle : {0.01f, 0.003f, 0.001f}) {
    char name[64];
    std::snprintf(name, sizeof name, "adaptive angle %g", angle);
    sweep.push_back(
        withTessellation(name, "adaptive", {TessellationMode::CrackFree, TessellationMetric::Angle, angle, 5}));
  }
  for (int level = 1; level <= 4; ++level)
    sweep.push_back(withTessellation("full level " + std::to_string(level), "full",
                                     {TessellationMode::CrackFree, TessellationMetric::Pixels, 0.0f, level}));
  for (float scale : {0.5f, 2.0f}) {
    char name[64];
    std::snprintf(name, sizeof name, "G-buffer x%g", scale);
    AccuracySetting setting{name, "G-buffer", {}};
    setting.settings.gbufferScale = scale;
    sweep.push_back(setting);
  }
  AccuracySetting half{"G-buffer RGBA16F", "G-buffer", {}};
  half.settings.gbufferPrecision = passes::GBufferPrecision::Float16;
  sweep.push_back(half);
  // Every other row ray-casts the pixels its virtual objects leave uncovered; this one shows what
  // the virtual objects alone leave there.
  AccuracySetting gaps{"uncovered pixels show the background", "virtual objects alone", {}};
  gaps.settings.rayCastUncovered = false;
  sweep.push_back(gaps);
  // Szabo's ray-hierarchy search in place of the crosshair search, bare and with the default tessellation.
  AccuracySetting hierarchy = withTessellation("hierarchy search, no tessellation", "hierarchy",
                                               {TessellationMode::None, TessellationMetric::Pixels, 1.0f, 0});
  hierarchy.settings.search = passes::SearchStrategy::Hierarchy;
  sweep.push_back(hierarchy);
  hierarchy = {"hierarchy search", "hierarchy", {}};
  hierarchy.settings.search = passes::SearchStrategy::Hierarchy;
  sweep.push_back(hierarchy);
  // Ofek & Rappoport's explosion map: the paper's whole method (map look-ups, triangles drawn where
  // they lie) at three map sizes, then its look-ups refined by the crosshair search.
  for (int side : {128, 256, 512}) {
    AccuracySetting map{"explosion map " + std::to_string(side), "explosion map", {}};
    map.settings.search = passes::SearchStrategy::ExplosionMap;
    map.settings.explosionMapSize = side;
    map.settings.virtualPixels = passes::VirtualPixels::AsPlaced;
    sweep.push_back(map);
  }
  AccuracySetting mirrored{"explosion map 256, mirrored (the paper)", "explosion map", {}};
  mirrored.settings.search = passes::SearchStrategy::ExplosionMap;
  mirrored.settings.explosionMirrorPlacement = true;
  mirrored.settings.virtualPixels = passes::VirtualPixels::AsPlaced;
  sweep.push_back(mirrored);
  AccuracySetting refined{"explosion map 256, refined", "explosion map", {}};
  refined.settings.search = passes::SearchStrategy::ExplosionMap;
  refined.settings.explosionRefine = true;
  sweep.push_back(refined);
  // (A scene with such a mirror already searches its mesh: its hierarchy rows are the general path.)
  if (std::any_of(scene.objects.begin(), scene.objects.end(), approximatesAnExactShape))
    for (const glm::ivec2 mesh : {glm::ivec2(32, 16), glm::ivec2(64, 32), glm::ivec2(128, 64), glm::ivec2(256, 128)})
      sweep.push_back({"mesh " + std::to_string(mesh.x) + "x" + std::to_string(mesh.y), "mesh", {}, mesh});
  // A scene with a mirror declared as an extrusion: every row above searches its mesh (the general
  // path), and one solves it exactly by Ofek & Rappoport's 2-D reduction instead.
  if (std::any_of(scene.objects.begin(), scene.objects.end(),
                  [](const scene::SceneObject& object) { return object.mirror && object.mirror->extrusion; })) {
    for (AccuracySetting& setting : sweep) setting.settings.solveExtrusions = false;
    sweep.push_back({"extrusion solved in 2-D", "extrusion", {}});
  }
  // Every row above measures the search, whatever the mirror's size on screen; the last casts every
  // mirror pixel's reflected ray instead (what the planner picks where it predicts that cheaper).
  for (AccuracySetting& setting : sweep) setting.settings.rayCast = passes::RayCastRule::Never;
  AccuracySetting rayCast{"ray-cast every mirror", "ray-cast", {}};
  rayCast.settings.rayCast = passes::RayCastRule::Always;
  sweep.push_back(rayCast);
  return sweep;
}

namespace {

// The ray-traced reference of every pose of the path.
struct References {
  std::vector<reference::ReferenceImage> images;
  double medianMilliseconds = 0.0;
  // Each pose's geometry, for the live estimate's pixel tracers.
  std::unique_ptr<reference::RayTracer> tracer;
  std::vector<std::shared_ptr<const reference::PosedScene>> posed;
};

Result<References> traceReferences(const std::shared_ptr<const scene::Scene>& scene,
                                   const std::vector<scene::ScenePose>& path, const AccuracyBenchOptions& options,
                                   const std::string& what,
                                   const std::function<void(const std::string& step)>& progress) {
  auto tracer = reference::RayTracer::create(scene);
  if (!tracer) return Error{tracer.error()};
  References references;
  std::vector<double> times;
  for (std::size_t i = 0; i < path.size(); ++i) {
    progress(what + ", pose " + std::to_string(i + 1) + "/" + std::to_string(path.size()));
    // One hierarchy per pose, for the reference image and the live estimates; timed with the image.
    const auto start = std::chrono::steady_clock::now();
    auto posed = (*tracer)->posedScene(path[i]);
    if (!posed) return Error{posed.error()};
    auto truth = (*tracer)->render(*posed, path[i].camera, {options.width, options.height, 1, 0});
    if (!truth) return Error{truth.error()};
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    references.images.push_back(std::move(*truth));
    references.posed.push_back(std::move(*posed));
  }
  references.medianMilliseconds = median(times);
  references.tracer = std::move(*tracer);
  return references;
}

// One setting along the path, compared with `truths`.
Result<AccuracyRow> measureSetting(render::Renderer& r, const std::vector<scene::ScenePose>& path,
                                   const References& references, const AccuracyBenchOptions& options,
                                   const AccuracySetting& setting) {
  const std::vector<reference::ReferenceImage>& truths = references.images;
  const ReflectionMethod method = setting.settings.method;
  const bool measurePoints = hasExactMirror(r.scene()) && method == ReflectionMethod::Search;
  // Warm-up at the first pose: buffer sizes, shader caches, coherence seeds.
  if (auto warm = r.render(path.front(), options.width, options.height, setting.settings); !warm)
    return Error{setting.name + ": " + warm.error()};
  std::vector<double> times, psnrs, ssims, mismatches, estimates, estimateTimes;
  std::size_t covered = 0;
  std::vector<std::uint64_t> drawn, searched;
  ReflectionPointErrors points;
  for (std::size_t i = 0; i < path.size(); ++i) {
    auto frame = r.render(path[i], options.width, options.height, setting.settings);
    if (!frame) return Error{setting.name + ": " + frame.error()};
    times.push_back(frame->timings.totalMilliseconds);
    auto comparison = compareWithReference(*frame, truths[i]);
    if (!comparison) return Error{setting.name + ": " + comparison.error()};
    psnrs.push_back(comparison->psnr);
    ssims.push_back(comparison->ssim);
    mismatches.push_back(comparison->mirrorMismatch);
    auto live = sampleAgainstReference(*references.tracer, references.posed[i], path[i].camera, *frame, i);
    if (!live) return Error{setting.name + ": the live estimate: " + live.error()};
    const reference::ShareEstimate& estimate = live->sample.mismatch;
    estimates.push_back(estimate.share());
    estimateTimes.push_back(live->milliseconds);
    covered += estimate.low <= comparison->mirrorMismatch && comparison->mirrorMismatch <= estimate.high ? 1 : 0;
    // A frame that searched nothing ray-cast its mirrors: no virtual triangles, no reflection points.
    const bool searchedAny = frame->search.searched > 0;
    drawn.push_back(method == ReflectionMethod::Search && !searchedAny ? 0
                                                                       : 3 * reflectionTriangles(r, *frame, method));
    searched.push_back(frame->search.searched + frame->tessellation.midpointSearches.searched);
    if (measurePoints && searchedAny) {
      ReflectionPointErrors errors = measureReflectionPoints(r, path[i], *frame);
      points.pixels.insert(points.pixels.end(), errors.pixels.begin(), errors.pixels.end());
    }
  }
  AccuracyRow row{r.scene().name, setting.name, setting.family};
  row.frameMilliseconds = median(times);
  row.psnr = mean(psnrs);
  row.ssim = mean(ssims);
  row.mirrorMismatch = mean(mismatches);
  row.estimateMean = mean(estimates);
  row.estimateCoverage = static_cast<double>(covered) / static_cast<double>(path.size());
  row.estimateMilliseconds = median(estimateTimes);
  if (!points.pixels.empty()) {
    row.pointErrorP99 = points.percentile(0.99);
    row.pointErrorMax = points.percentile(1.0);
  }
  row.reflectionVertices = medianOf(drawn);
  row.searches = static_cast<std::uint32_t>(medianOf(searched));
  return row;
}

}  // namespace

Result<std::vector<AccuracyRow>> benchmarkAccuracy(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene,
                                                   const AccuracyBenchOptions& options,
                                                   const std::vector<AccuracySetting>& sweep,
                                                   const std::function<void(const std::string& step)>& progress) {
  if (options.poses < 1) return Error{"the camera path needs at least one pose"};
  std::vector<scene::ScenePose> path;
  for (int i = 0; i < options.poses; ++i) path.push_back(pathPose(*scene, options, i));

  // One reference per pose, shared by every setting of the scene as given: the ray tracer is the slow part.
  auto references = traceReferences(scene, path, options, "ray-traced reference", progress);
  if (!references) return Error{references.error()};
  std::vector<AccuracyRow> rows;
  AccuracyRow reference{scene->name, "ray-traced reference", "reference"};
  reference.reference = true;
  reference.frameMilliseconds = references->medianMilliseconds;
  reference.psnr = 100.0;  // the PSNR ceiling compareWithReference reports for identical images
  reference.ssim = 1.0;
  rows.push_back(reference);

  auto renderer = render::Renderer::create(context, scene);
  if (!renderer) return Error{renderer.error()};
  for (const AccuracySetting& setting : sweep) {
    progress(setting.name);
    Result<AccuracyRow> row = Error{""};
    if (setting.mirrorMesh) {
      // Another mesh is another scene: its own renderer and its own references.
      auto variant = std::make_shared<const scene::Scene>(withMirrorMeshes(*scene, *setting.mirrorMesh));
      auto truths = traceReferences(variant, path, options, setting.name + ": ray-traced reference", progress);
      if (!truths) return Error{setting.name + ": " + truths.error()};
      auto variantRenderer = render::Renderer::create(context, variant);
      if (!variantRenderer) return Error{setting.name + ": " + variantRenderer.error()};
      row = measureSetting(**variantRenderer, path, *truths, options, setting);
    } else {
      row = measureSetting(**renderer, path, *references, options, setting);
    }
    if (!row) return Error{row.error()};
    rows.push_back(std::move(*row));
  }
  markParetoFront(rows);
  return rows;
}

void markParetoFront(std::vector<AccuracyRow>& rows) {
  const auto dominates = [](const AccuracyRow& a, const AccuracyRow& b) {
    return a.frameMilliseconds <= b.frameMilliseconds && a.mirrorMismatch <= b.mirrorMismatch &&
           (a.frameMilliseconds < b.frameMilliseconds || a.mirrorMismatch < b.mirrorMismatch);
  };
  for (AccuracyRow& row : rows) {
    row.pareto = !row.reference && std::none_of(rows.begin(), rows.end(), [&](const AccuracyRow& other) {
      return !other.reference && dominates(other, row);
    });
  }
}

}  // namespace specula::bench
