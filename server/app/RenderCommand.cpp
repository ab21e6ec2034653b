// `specula render`: one deterministic frame of a scene to a PNG or JPEG file, with per-stage timings.
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "base/CommandFailure.h"
#include "base/CommandLine.h"
#include "base/Percentile.h"
#include "app/Commands.h"
#include "app/GlSetup.h"
#include "app/SceneSource.h"
#include "app/ReflectionOptions.h"
#include "bench/ImageComparison.h"
#include "encode/JpegEncoder.h"
#include "encode/PngEncoder.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "math/SamplePattern.h"
#include "scene/Deformation.h"
#include "scene/ScenePose.h"

namespace specula::app {

namespace {

constexpr int kMaxFrameSide = 8192;
constexpr int kJpegQuality = 92;

CommandLine renderOptions() {
  std::vector<OptionSpec> specs = {
      {"scene", "NAME|FILE", kSceneOptionHelp, "checker-sphere"},
      {"size", "WxH", "frame size in pixels", "640x480"},
      {"eye", "x,y,z", "camera position, world metres", ""},
      {"target", "x,y,z", "point the camera looks at", ""},
      {"up", "x,y,z", "camera up direction", ""},
      {"fov", "DEG", "vertical field of view in degrees", ""},
      {"time", "SECONDS", "scene time: animations are evaluated at this instant", "0"},
      {"method", "METHOD",
       "search | explosion-map (= search with --search explosion-map) | environment-map | raytrace | none", "search"},
  };
  specs = withSceneChoice(std::move(specs));
  for (OptionSpec& spec : reflectionOptions()) specs.push_back(std::move(spec));
  specs.push_back(samplesOption(math::kStillFrameSamples));
  specs.push_back({"out", "FILE", "output image; .png (lossless) or .jpg", "<scene>.png"});
  specs.push_back({"verify", "",
                   "also ray-trace the exact image (CPU) and print how far the frame is from it: PSNR, SSIM, the "
                   "share of mirror pixels wrong, and the live estimate a stream would have shown",
                   ""});
  specs.push_back(glOption());
  return CommandLine(
      "specula render [options]",
      "Renders one frame of a scene deterministically and prints the time each stage took.\n"
      "Camera options override the scene's (animated) camera one value at a time.\n"
      "Methods: search = virtual objects from the screen-space reflection-point search (GL);\n"
      "explosion-map = virtual objects placed by Ofek & Rappoport's explosion maps instead of a search (GL);\n"
      "environment-map = the usual engine shortcut, a cube map from each mirror's centre (GL; no parallax);\n"
      "raytrace = the exact reference (Embree, CPU); none = mirrors in their own colour only (GL).",
      std::move(specs));
}

// <scene>.png in the working folder; a scene file's name cannot steer the write elsewhere.
std::string defaultOutputName(const std::string& sceneName) {
  std::string name;
  for (char c : sceneName) name += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
  return (name.empty() ? "frame" : name) + ".png";
}

constexpr CommandFailure fail{"specula render"};

// Applies --eye/--target/--up/--fov over the posed camera.
Status overrideCamera(const CommandLine& options, math::Camera& camera) {
  for (auto [name, field] : {std::pair{"eye", &camera.eye}, {"target", &camera.target}, {"up", &camera.up}}) {
    if (!options.has(name)) continue;
    auto value = options.vector3(name);
    if (!value) return Error{value.error()};
    *field = *value;
  }
  if (options.has("fov")) {
    auto fov = options.number("fov");
    if (!fov) return Error{fov.error()};
    camera.fovYDegrees = static_cast<float>(*fov);
  }
  if (auto problem = math::cameraProblem(camera)) return Error{"bad camera: " + *problem};
  return {};
}

std::string formatMilliseconds(double milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", milliseconds);
  return text;
}

const char* surfaceName(scene::SurfaceKind kind) {
  switch (kind) {
    case scene::SurfaceKind::Convex: return "convex";
    case scene::SurfaceKind::Concave: return "concave";
    case scene::SurfaceKind::Saddle: return "saddle";
  }
  return "?";
}

// What a planned part does with its reflected objects, as the plan line says it.
const char* methodWords(passes::PartMethod method) {
  switch (method) {
    case passes::PartMethod::VirtualObjects: return "searched";
    case passes::PartMethod::RayCast: return "ray-cast";
    case passes::PartMethod::OwnColour: return "own colour, drew";
    case passes::PartMethod::EnvironmentMap: return "environment map of";
  }
  return "?";
}

// The patch tessellation of the frame's parametric meshes, as `render` prints it.
std::string describePatchTessellation(const passes::PatchTessellationMeasure& measure) {
  const std::vector<double> areas(measure.pixelAreas.begin(), measure.pixelAreas.end());
  char line[256];
  std::snprintf(line, sizeof line,
                "parametric: %zu patches -> %zu triangles (tessellated for this view; %zu on screen, pixel area p10 / "
                "p50 / p90 %.1f / %.1f / %.1f)\n",
                measure.patches, measure.triangles, areas.size(), nearestRankPercentile(areas, 0.1),
                nearestRankPercentile(areas, 0.5), nearestRankPercentile(areas, 0.9));
  return line;
}

// Per-stage timings, the plan and search statistics of a GL frame, as `render` prints them.
std::string describeFrame(const scene::Scene& scene, const render::RenderedFrame& frame,
                          const passes::ReflectionSettings& settings) {
  std::string text =
      "frame " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
      (frame.samples > 1 ? ", " + std::to_string(frame.samples) + " samples a pixel, pass times summed over them"
                         : "") +
      ":";
  for (const render::StageTiming& stage : frame.timings.stages)
    text += " " + stage.name + " " + formatMilliseconds(stage.milliseconds) + " ms,";
  text += " total " + formatMilliseconds(frame.timings.totalMilliseconds) + " ms\n";
  if (!frame.drawnMirrors.empty()) {
    const passes::SearchStatistics& search = frame.search;
    char line[320];
    std::snprintf(
        line, sizeof line,
        "reflections: %zu mirrors, %u vertices searched (%s), steps mean %.2f max %u, %u cold starts, %u hidden, "
        "%u unsolved",
        frame.drawnMirrors.size(), search.searched, passes::searchStrategyName(settings.search),
        search.searched ? static_cast<double>(search.totalSteps) / search.searched : 0.0, search.maxSteps,
        search.coldStarts, search.hidden, search.unsolved);
    text += line;
    if (settings.search == passes::SearchStrategy::ExplosionMap) {
      std::snprintf(line, sizeof line, " (explosion map %dx%d%s: steps are map look-ups%s)", settings.explosionMapSize,
                    settings.explosionMapSize, settings.explosionRefine ? ", refined" : "",
                    settings.explosionRefine ? " plus climbing windows" : "");
      text += line;
    }
    if (settings.search == passes::SearchStrategy::Hierarchy) {
      std::snprintf(line, sizeof line, ", %u in no cone until enlarged, %u in none even then", search.enlarged,
                    search.inNoCone);
      text += line;
    }
    const auto extrusions = std::ranges::count_if(frame.drawnMirrors, [&](std::size_t m) {
      return scene.objects[m].mirror && scene.objects[m].mirror->extrusion;
    });
    if (extrusions > 0)
      text += settings.solveExtrusions
                  ? "; extrusion mirrors (" + std::to_string(extrusions) + ") solved by the 2-D reduction, 0 steps each"
                  : "; extrusion mirrors (" + std::to_string(extrusions) + ") searched (--extrusions search)";
    text += "\n";
  }
  for (const render::MirrorPlanSummary& mirror : frame.plan) {
    char line[512];
    std::snprintf(
        line, sizeof line,
        "plan: mirror '%.64s' part %d (%s, ~%.0f px): %s %zu objects (%zu vertices); %zu objects, %zu vertices left "
        "out "
        "(%s); %zu objects (%zu vertices) under the %g px error budget; %zu uncovered pixels ray-cast; cast on %zu of "
        "%zu object tiles; predicted: searching %.1f ms, ray-casting %.1f ms (the llvmpipe fit times the rates "
        "measured here, "
        "%.2f, %.2f)\n",
        scene.objects[mirror.mirrorObject].name.c_str(), mirror.part, surfaceName(mirror.kind), mirror.projectedPixels,
        mirror.method != passes::PartMethod::RayCast ? methodWords(mirror.method)
        : scene.objects[mirror.mirrorObject].mirror->twoSided()
            ? "ray-cast (an open mesh: only a closed one is searched)"
        : scene::deforms(scene, mirror.mirrorObject)
            ? "ray-cast (a mirror that changes shape: its parts' curvature is not known each frame)"
            : methodWords(mirror.method),
        mirror.searchedObjects, mirror.searchedVertices, mirror.culledObjects, mirror.culledVertices,
        mirror.facesAway ? "the part faces away from the eye" : "behind it or in its shadow", mirror.belowBudgetObjects,
        mirror.belowBudgetVertices, static_cast<double>(settings.errorBudgetPixels), mirror.uncoveredRayCast,
        mirror.castTiles.listed, mirror.castTiles.possible, mirror.predictedCost.search, mirror.predictedCost.rayCast,
        frame.planner.rates.search, frame.planner.rates.rayCast);
    text += line;
  }
  const passes::TessellationStatistics& tessellation = frame.tessellation;
  if (!tessellation.trianglesPerRound.empty() || tessellation.predictedUnsplitObjects > 0) {
    text += "tessellation: " + std::to_string(tessellation.inputTriangles) + " -> " +
            std::to_string(tessellation.finishedTriangles) + " triangles; working per round";
    for (std::uint32_t count : tessellation.trianglesPerRound) text += " " + std::to_string(count);
    text += "; " + std::to_string(tessellation.midpointSearches.searched) + " midpoint searches (" +
            std::to_string(tessellation.midpointSearches.coldStarts) + " from the pyramid); " +
            std::to_string(tessellation.predictedUnsplitObjects) +
            " objects planned unsplit (no edge image can reach the threshold)";
    text += tessellation.capped ? "; CAPPED at the triangle limit: raise --threshold or lower --level\n" : "\n";
  }
  return text;
}

// `frame` against the ray tracer's image of the same pose, size and samples: the full comparison, and
// beside it what the live estimate of a stream would have said of this frame.
Result<std::string> verifyAgainstRayTracer(const std::shared_ptr<const scene::Scene>& scene,
                                           const scene::ScenePose& pose, const render::RenderedFrame& frame) {
  auto tracer = reference::RayTracer::create(scene);
  if (!tracer) return Error{tracer.error()};
  reference::RayTracerOptions traced;
  traced.width = frame.width;
  traced.height = frame.height;
  traced.samples = frame.samples;
  // One hierarchy for the image and the estimate; the time printed is the image's, its build included.
  const auto start = std::chrono::steady_clock::now();
  auto posed = (*tracer)->posedScene(pose);
  if (!posed) return Error{"--verify: " + posed.error()};
  auto truth = (*tracer)->render(*posed, pose.camera, traced);
  if (!truth) return Error{"--verify: " + truth.error()};
  truth->milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto comparison = bench::compareWithReference(frame, *truth);
  if (!comparison) return Error{"--verify: " + comparison.error()};
  auto live = bench::sampleAgainstReference(**tracer, std::move(*posed), pose.camera, frame, 0);
  if (!live) return Error{"--verify: " + live.error()};
  const reference::ShareEstimate& e = live->sample.mismatch;
  char text[512];
  std::snprintf(text, sizeof text,
                "verify: against the ray tracer (%d rays a pixel, %s ms): PSNR %.2f dB, SSIM %.4f, mirror pixels "
                "wrong %.3f %%; the live estimate from %zu of them: %.3f %% (95 %%: %.3f to %.3f %%), %s ms\n",
                frame.samples, formatMilliseconds(truth->milliseconds).c_str(), comparison->psnr, comparison->ssim,
                100.0 * comparison->mirrorMismatch, e.sampled, 100.0 * e.share(), 100.0 * e.low, 100.0 * e.high,
                formatMilliseconds(live->milliseconds).c_str());
  return std::string(text);
}

}  // namespace

int runRender(std::span<const std::string> arguments) {
  CommandLine options = renderOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  auto size = options.size("size", kMaxFrameSide);
  auto time = options.number("time");
  auto samples = parseSamples(options);
  if (!size) return fail(size.error());
  if (!samples) return fail(samples.error());
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  if (!time) return fail(time.error());

  auto sceneChoice = parseSceneChoice(options);
  if (!sceneChoice) return fail(sceneChoice.error());
  auto scene = loadScene(options.text("scene"), *sceneChoice);
  if (!scene) return fail(scene.error());
  std::string out = options.has("out") ? options.text("out") : defaultOutputName((*scene)->name);
  const std::string extension = std::filesystem::path(out).extension().string();
  const bool jpeg = extension == ".jpg" || extension == ".jpeg";
  if (!jpeg && extension != ".png") return fail("--out must end in .png, .jpg or .jpeg, got '" + out + "'");

  scene::ScenePose pose = scene::ScenePose::at(**scene, *time);
  if (Status status = overrideCamera(options, pose.camera); !status) return fail(status.error());

  const std::string method = options.text("method");
  if (method != "search" && method != "explosion-map" && method != "environment-map" && method != "raytrace" &&
      method != "none")
    return fail("--method expects search, explosion-map, environment-map, raytrace or none, got '" + method + "'");
  auto settings = parseReflectionOptions(options);
  if (!settings) return fail(settings.error());
  if (method == "explosion-map") {
    if (options.has("search") && settings->search != passes::SearchStrategy::ExplosionMap)
      return fail("--method explosion-map places vertices by the maps; it cannot take --search " +
                  options.text("search"));
    settings->search = passes::SearchStrategy::ExplosionMap;
    if (!options.has("virtual-pixels"))
      settings->virtualPixels = passes::VirtualPixels::AsPlaced;  // the paper's whole method
  }
  settings->method = method == "none"              ? passes::ReflectionMethod::None
                     : method == "environment-map" ? passes::ReflectionMethod::EnvironmentMap
                                                   : passes::ReflectionMethod::Search;

  std::vector<std::uint8_t> rgba;
  std::string timings, parametric;
  if (method == "raytrace") {
    auto tracer = reference::RayTracer::create(*scene);
    if (!tracer) return fail(tracer.error());
    reference::RayTracerOptions traced;
    traced.width = size->first;
    traced.height = size->second;
    traced.samples = *samples;
    auto image = (*tracer)->render(pose, traced);
    if (!image) return fail(image.error());
    rgba = std::move(image->rgba);
    timings = "frame " + std::to_string(size->first) + "x" + std::to_string(size->second) + ": raytrace " +
              formatMilliseconds(image->milliseconds) + " ms (CPU, Embree, " + std::to_string(*samples) +
              " rays a pixel)\n";
  } else {
    auto context = openGlContext(options.text("gl"));
    if (!context) return fail(context.error());
    auto renderer = render::Renderer::create(**context, *scene);
    if (!renderer) return fail(renderer.error());
    auto frame = (*renderer)->render(pose, size->first, size->second, *settings, *samples);
    if (!frame) return fail(frame.error());
    auto patches = (*renderer)->measurePatchTessellation(pose, *frame);
    if (!patches) return fail(patches.error());
    if (patches->patches > 0) parametric = describePatchTessellation(*patches);
    timings = describeFrame(**scene, *frame, *settings);
    if (options.has("verify")) {
      auto verified = verifyAgainstRayTracer(*scene, pose, *frame);
      if (!verified) return fail(verified.error());
      timings += *verified;
    }
    rgba = std::move(frame->rgba);
  }

  const encode::ImageView view{rgba.data(), size->first, size->second};
  encode::JpegEncoder jpegEncoder;
  auto bytes = jpeg ? jpegEncoder.encode(view, kJpegQuality) : encode::encodePng(view);
  if (!bytes) return fail(bytes.error());
  {
    std::ofstream file(out, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(bytes->data()), static_cast<std::streamsize>(bytes->size()));
    if (!file) return fail("could not write '" + out + "': check the folder exists and is writable");
  }

  const scene::Scene& s = **scene;
  std::printf("scene %s: %zu objects, %zu vertices, %zu triangles, %zu mirrors; time %.3f s\n", s.name.c_str(),
              s.objects.size(), s.vertexCount(), s.triangleCount(), s.mirrorCount(), *time);
  std::fputs(parametric.c_str(), stdout);
  std::fputs(timings.c_str(), stdout);
  std::printf("wrote %s (%zu bytes)\n", out.c_str(), bytes->size());
  return 0;
}

}  // namespace specula::app
