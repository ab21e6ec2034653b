// `specula bench`: every method's cost and accuracy on the built-in scenes, as a table, CSV and JSON.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "base/CommandLine.h"
#include "app/Commands.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "app/Plotting.h"
#include "app/ReflectionOptions.h"
#include "app/SceneSource.h"
#include "bench/AccuracyBenchmark.h"
#include "bench/AccuracyReport.h"
#include "bench/SceneReport.h"
#include "bench/TessellationReport.h"
#include "bench/SceneBenchmark.h"
#include "math/SamplePattern.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

namespace {

constexpr int kMaxBenchSide = 4096;
constexpr int kMaxFrames = 10000;

CommandLine benchOptions() {
  std::vector<OptionSpec> specs = {
      {"scenes", "LIST", "comma-separated built-in scene names, glTF files (.gltf, .glb) or JSON scene files", "all built-in scenes"},
      {"size", "WxH", "frame size in pixels", "640x480"},
      {"sizes", "LIST", "comma-separated frame sizes, each scene measured at each (instead of --size)", "--size"},
      {"frames", "N", "warm frames measured after the cold one", "60"},
      {"cold-size", "WxH|none", "size of the extra cold-start frame (steps only)", "1280x720"},
      {"no-reference", "", "skip the ray-traced reference (PSNR, SSIM, ray-tracing time)", ""},
      {"pass-timing", "HOW",
       "per-pass (each pass timed: GPU timestamps, or on llvmpipe a glFinish after each, which slows the frame) | frame "
       "(whole frames as served, no wait between passes; pass columns empty)",
       "per-pass"},
      samplesOption(math::kStillFrameSamples, "samples a pixel of the still frame compared with the ray tracer (which takes the same): 1, 2, 4, 8 or 16"),
      {"csv", "FILE", "CSV output, one row per scene", "bench.csv"},
      {"json", "FILE", "JSON output", "bench.json"},
      glOption(),
  };
  for (OptionSpec& spec : gltfSceneOptions()) specs.push_back(std::move(spec));
  for (OptionSpec& spec : searchOptions()) specs.push_back(std::move(spec));
  for (OptionSpec& spec : planOptions()) specs.push_back(std::move(spec));
  return CommandLine(
      "specula bench [tessellation|accuracy|serve] [--scenes LIST] [--gltf-scene N] [--camera N] [--size WxH | --sizes LIST] [--frames N] [--cold-size WxH|none] [--no-reference] [--pass-timing per-pass|frame] [--samples N] "
      "[--search crosshair|hierarchy|explosion-map] [--explosion-map-size N] [--explosion-refine on|off] [--explosion-placement eye-ray|mirror] [--virtual-pixels exact-hit|as-placed] [--extrusions solve|search] "
      "[--plan needed|everything] [--ray-cast cheaper|never|always] [--error-budget PX] [--uncovered ray-cast|background] [--csv FILE] [--json FILE] [--gl BACKEND]",
      "Measures each scene along its own animation at 60 frames per second: median time per pass (after a\n"
      "cold first frame, reported apart because it includes shader compilation), search steps with\n"
      "frame-to-frame coherence and from a cold start, reflection-point error in pixels against the exact\n"
      "solvers (scenes with an analytic sphere or extrusion mirror, where it searches), and the last pose as an\n"
      "anti-aliased still frame (--samples) against the ray-traced reference at the same samples (PSNR, SSIM, share\n"
      "of mismatched mirror pixels); \"trace ms\" and \"x trace\" set the warm frames (one sample) against one ray\n"
      "a pixel. \"still frames\" times the last pose at 1, 4 and 8 samples: what anti-aliasing costs. \"floor\" is\n"
      "the last pose drawn with no reflection (--method none): the scene's own raster, below which no method\n"
      "can go. --plan everything turns the frame planner off (no culling, no ray-cast mirrors) for comparison.\n"
      "\"searches\" renders the first frames again with each search (crosshair, hierarchy, explosion-map\n"
      "unrefined), every mirror part searched: median ms of the search stages (the explosion map's build\n"
      "included), steps (map look-ups for the explosion map), and the hierarchy's enlarged and in-no-cone vertices.\n"
      "Prints a table and writes the same numbers as CSV and JSON.\n"
      "`specula bench tessellation --help` describes the tessellation sweep, `specula bench accuracy --help`\n"
      "the accuracy-against-time report.",
      std::move(specs));
}

int fail(const std::string& message) {
  std::cerr << "specula bench: " << message << "\n";
  return 1;
}

std::vector<std::string> sceneList(const CommandLine& options, const std::vector<std::string>& defaults) {
  std::vector<std::string> names;
  if (!options.has("scenes")) return defaults;
  std::stringstream list(options.text("scenes"));
  for (std::string name; std::getline(list, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

// Loads every scene up front, so a typo fails before the long part.
Result<std::vector<std::shared_ptr<const scene::Scene>>> loadScenes(const std::vector<std::string>& names,
                                                                    const scene::GltfSceneChoice& choice = {}) {
  if (names.empty()) return Error{"--scenes names no scene"};
  std::vector<std::shared_ptr<const scene::Scene>> scenes;
  for (const std::string& name : names) {
    auto loaded = loadScene(name, choice);
    if (!loaded) return Error{loaded.error()};
    scenes.push_back(*loaded);
  }
  return scenes;
}

CommandLine tessellationBenchOptions() {
  return CommandLine(
      "specula bench tessellation [--scenes LIST] [--size WxH] [--frames N] [--time SECONDS] [--csv FILE] "
      "[--json FILE] [--gl BACKEND]",
      "Measures every tessellation setting on each scene at one pose: none; full tessellation at levels 1-5;\n"
      "crack-free adaptive with Szabo's angle metric (0.1 ... 0.001) and the pixel metric (2, 1, 0.5 px) at\n"
      "level 5. For each: triangles and vertices drawn, reflection searches (scene vertices and new edge\n"
      "midpoints), median "
      "frame and tessellation-pass time, and PSNR, SSIM and mirror mismatch against the ray-traced reference.\n"
      "Then names, per scene, the adaptive setting with the fewest vertices that is as accurate as full level 4.",
      {
          {"scenes", "LIST", "comma-separated built-in scene names or JSON scene files", "quad,teapot-table,checker-sphere,kitchen"},
          {"size", "WxH", "frame size in pixels", "640x480"},
      {"sizes", "LIST", "comma-separated frame sizes, each scene measured at each (instead of --size)", "--size"},
          {"frames", "N", "timed frames per setting, after a warm-up frame", "3"},
          {"time", "SECONDS", "scene time of the pose measured", "0"},
          {"csv", "FILE", "CSV output, one row per scene and setting", "tessellation.csv"},
          {"json", "FILE", "JSON output", "tessellation.json"},
          glOption(),
      });
}

int runTessellationBench(std::span<const std::string> arguments) {
  CommandLine options = tessellationBenchOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  bench::TessellationBenchOptions settings;
  auto size = options.size("size", kMaxBenchSide);
  auto frames = options.integer("frames", 1, kMaxFrames);
  auto time = options.number("time");
  if (!size) return fail(size.error());
  if (!frames) return fail(frames.error());
  if (!time) return fail(time.error());
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  settings.frames = *frames;
  settings.time = *time;
  for (const char* output : {"csv", "json"})
    if (Status status = checkWritable(options.text(output)); !status) return fail(status.error());
  auto scenes = loadScenes(sceneList(options, {"quad", "teapot-table", "checker-sphere", "kitchen"}));
  if (!scenes) return fail(scenes.error());
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  const std::vector<passes::TessellationSettings> sweep = bench::tessellationSweep();
  std::vector<bench::TessellationBenchRow> rows;
  std::string goals;
  for (std::size_t i = 0; i < scenes->size(); ++i) {
    const std::string& name = (*scenes)[i]->name;
    auto result = bench::benchmarkTessellation(**context, (*scenes)[i], settings, sweep,
                                               [&](std::size_t index, const std::string& setting) {
                                                 std::fprintf(stderr, "bench tessellation [%zu/%zu] %s: [%zu/%zu] %s\n", i + 1,
                                                              scenes->size(), name.c_str(), index + 1, sweep.size(), setting.c_str());
                                               });
    if (!result) return fail(name + ": " + result.error());
    const auto best = bench::cheapestMatchingFullLevel4(*result);
    const auto full = std::find_if(result->begin(), result->end(), [](const auto& row) {
      return row.tessellation.threshold == 0.0f && row.tessellation.maxLevel == 4;
    });
    char line[256];
    if (best && full != result->end())
      std::snprintf(line, sizeof line, "%s: full level 4 has mismatch %.4f with %u vertices; %s matches it with %u (%.0f %%)\n",
                    name.c_str(), full->mirrorMismatch, full->vertices(), best->setting.c_str(), best->vertices(),
                    100.0 * best->vertices() / std::max(1u, full->vertices()));
    else
      std::snprintf(line, sizeof line, "%s: no adaptive setting is as accurate as full level 4\n", name.c_str());
    goals += line;
    rows.insert(rows.end(), result->begin(), result->end());
  }
  std::fputs(bench::formatTessellationTable(rows).c_str(), stdout);
  std::fputs(goals.c_str(), stdout);
  for (const auto& [option, text] : {std::pair{"csv", bench::formatTessellationCsv(rows)}, {"json", bench::formatTessellationJson(rows)}}) {
    if (Status status = writeFile(options.text(option), text); !status) return fail(status.error());
    std::printf("wrote %s\n", options.text(option).c_str());
  }
  return 0;
}

CommandLine accuracyBenchOptions() {
  const bench::AccuracyBenchOptions defaults;
  return CommandLine(
      "specula bench accuracy [--scene NAME|FILE] [--size WxH] [--poses N] [--orbit DEG] [--seconds S] [--out DIR] "
      "[--no-plot] [--gl BACKEND]",
      "What each step of accuracy costs in time on one scene. Renders a camera path (the camera swings\n"
      "around its target while the scene animates) with every method and setting: the environment-map\n"
      "baseline, the search without tessellation, adaptive pixel and angle thresholds, full levels 1-4,\n"
      "the G-buffer at half and double resolution and in RGBA16F, the ray-hierarchy search, the explosion\n"
      "map (three sizes, the paper's placement, refined), every mirror ray-cast; on a scene with an\n"
      "extrusion mirror every row searches its mesh and one more solves it in 2-D. Ray-traces each pose\n"
      "once as the reference. Per setting: median frame time; mean PSNR, SSIM and mirror mismatch against the\n"
      "reference; reflection-point error (p99, max px) for sphere and extrusion mirrors; vertices drawn and\n"
      "searches per frame. Writes DIR/accuracy.csv, .json, .md (a Markdown table), .gp (a gnuplot\n"
      "script, data inline) and the plot it draws, DIR/accuracy.png and .svg: mirror mismatch against\n"
      "frame time with the Pareto front marked.",
      {
          {"scene", "NAME|FILE", "built-in scene name or JSON scene file", "checker-sphere"},
          {"size", "WxH", "frame size in pixels", "640x480"},
      {"sizes", "LIST", "comma-separated frame sizes, each scene measured at each (instead of --size)", "--size"},
          {"poses", "N", "camera-path poses per setting, each timed and compared", std::to_string(defaults.poses)},
          {"orbit", "DEG", "how far the camera swings around its target along the path, 0 to 180",
           std::to_string(static_cast<int>(defaults.orbitDegrees))},
          {"seconds", "S", "scene time the path spans (animation), 0 to 3600", "0.5"},
          {"out", "DIR", "output folder, created if missing", "accuracy"},
          {"no-plot", "", "skip the PNG and SVG (no gnuplot needed); the .gp script is still written", ""},
          glOption(),
      });
}

int runAccuracyBench(std::span<const std::string> arguments) {
  CommandLine options = accuracyBenchOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  bench::AccuracyBenchOptions settings;
  auto size = options.size("size", kMaxBenchSide);
  auto poses = options.integer("poses", 1, kMaxFrames);
  auto orbit = options.number("orbit");
  auto seconds = options.number("seconds");
  if (!size) return fail(size.error());
  if (!poses) return fail(poses.error());
  if (!orbit || *orbit < 0.0 || *orbit > 180.0) return fail("--orbit expects degrees from 0 to 180, got '" + options.text("orbit") + "'");
  if (!seconds || *seconds < 0.0 || *seconds > 3600.0)
    return fail("--seconds expects scene seconds from 0 to 3600, got '" + options.text("seconds") + "'");
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  std::tie(settings.width, settings.height) = *size;
  settings.poses = *poses;
  settings.orbitDegrees = *orbit;
  settings.seconds = *seconds;
  const bool plot = !options.has("no-plot");
  if (plot && !gnuplotAvailable()) return fail(std::string("the plot needs gnuplot: ") + kInstallGnuplot + ", or pass --no-plot");

  // Outputs and scene first, so a typo fails before the long part.
  const std::filesystem::path folder = options.text("out");
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return fail("could not create the output folder '" + folder.string() + "': " + error.message());
  const auto output = [&](const char* extension) { return (folder / ("accuracy." + std::string(extension))).string(); };
  for (const char* extension : {"csv", "json", "md", "gp"})
    if (Status status = checkWritable(output(extension)); !status) return fail(status.error());
  auto scene = loadScene(options.text("scene"));
  if (!scene) return fail(scene.error());
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  const std::vector<bench::AccuracySetting> sweep = bench::accuracySweep(**scene);
  // Each setting, and a ray-traced reference per pose for the scene and for every re-meshed mirror.
  const auto remeshed = static_cast<std::size_t>(std::count_if(sweep.begin(), sweep.end(), [](const auto& s) { return s.mirrorMesh.has_value(); }));
  const std::size_t steps = sweep.size() + (1 + remeshed) * static_cast<std::size_t>(settings.poses);
  std::size_t step = 0;
  const auto started = std::chrono::steady_clock::now();
  auto rows = bench::benchmarkAccuracy(**context, *scene, settings, sweep, [&](const std::string& what) {
    std::fprintf(stderr, "bench accuracy %s [%zu/%zu] %s (%.0f s so far)\n", (*scene)->name.c_str(), ++step, steps,
                 what.c_str(), std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  });
  if (!rows) return fail((*scene)->name + ": " + rows.error());

  char title[512];
  std::snprintf(title, sizeof title, "%s at %dx%d: %d poses, %.0f deg orbit, %s", (*scene)->name.c_str(), settings.width,
                settings.height, settings.poses, settings.orbitDegrees, (*context)->info().renderer.c_str());
  const std::string markdown = bench::formatAccuracyMarkdown(*rows, std::string("### ") + title);
  std::fputs(markdown.c_str(), stdout);
  for (const auto& [extension, text] : {std::pair{"csv", bench::formatAccuracyCsv(*rows)},
                                        {"json", bench::formatAccuracyJson(*rows)},
                                        {"md", markdown},
                                        {"gp", bench::accuracyPlotScript(*rows, title, "accuracy.png", "accuracy.svg")}}) {
    if (Status status = writeFile(output(extension), text); !status) return fail(status.error());
    std::printf("wrote %s\n", output(extension).c_str());
  }
  if (!plot) return 0;
  if (Status status = runGnuplot(folder.string(), "accuracy.gp"); !status) return fail(status.error());
  std::printf("wrote %s and %s\n", output("png").c_str(), output("svg").c_str());
  return 0;
}

}  // namespace

int runBench(std::span<const std::string> arguments) {
  if (!arguments.empty() && arguments.front() == "tessellation") return runTessellationBench(arguments.subspan(1));
  if (!arguments.empty() && arguments.front() == "serve") return runServeBench(arguments.subspan(1));
  if (!arguments.empty() && arguments.front() == "accuracy") return runAccuracyBench(arguments.subspan(1));
  CommandLine options = benchOptions();
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  bench::BenchOptions settings;
  auto frames = options.integer("frames", 1, kMaxFrames);
  if (options.has("size") && options.has("sizes")) return fail("give --size or --sizes, not both");
  std::vector<std::pair<int, int>> sizes;
  if (options.has("sizes")) {
    auto list = options.sizeList("sizes", kMaxBenchSide);
    if (!list) return fail(list.error());
    sizes = std::move(*list);
  } else {
    auto size = options.size("size", kMaxBenchSide);
    if (!size) return fail(size.error());
    sizes.push_back(*size);
  }
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  if (!frames) return fail(frames.error());
  settings.frames = *frames;
  if (options.text("cold-size") == "none") {
    settings.coldWidth = settings.coldHeight = 0;
  } else {
    auto coldSize = options.size("cold-size", kMaxBenchSide);
    if (!coldSize) return fail(coldSize.error());
    std::tie(settings.coldWidth, settings.coldHeight) = *coldSize;
  }
  settings.reference = !options.has("no-reference");
  const std::string passTiming = options.text("pass-timing");
  if (passTiming != "per-pass" && passTiming != "frame")
    return fail("--pass-timing expects per-pass or frame, got '" + passTiming + "'");
  settings.passTiming = passTiming == "frame" ? render::PassTiming::FrameOnly : render::PassTiming::PerPass;
  auto samples = parseSamples(options);
  if (!samples) return fail(samples.error());
  settings.stillSamples = *samples;
  if (Status status = parsePlanOptions(options, settings.reflection); !status) return fail(status.error());
  if (Status status = parseSearchOptions(options, settings.reflection); !status) return fail(status.error());
  std::vector<std::string> builtins;
  for (std::string_view name : scene::builtinSceneNames()) builtins.emplace_back(name);
  const std::vector<std::string> names = sceneList(options, builtins);

  // Check outputs and load every scene before the long part, so a typo fails at once.
  for (const char* output : {"csv", "json"})
    if (Status status = checkWritable(options.text(output)); !status) return fail(status.error());
  auto gltfChoice = parseGltfSceneOptions(options);
  if (!gltfChoice) return fail(gltfChoice.error());
  auto loaded = loadScenes(names, *gltfChoice);
  if (!loaded) return fail(loaded.error());
  const std::vector<std::shared_ptr<const scene::Scene>>& scenes = *loaded;
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  std::vector<bench::SceneBenchResult> results;
  const std::size_t runs = scenes.size() * sizes.size();
  for (std::size_t run = 0; run < runs; ++run) {
    const std::shared_ptr<const scene::Scene>& scene = scenes[run / sizes.size()];
    std::tie(settings.width, settings.height) = sizes[run % sizes.size()];
    std::fprintf(stderr, "bench [%zu/%zu] %s: %d frames at %dx%d%s ...\n", run + 1, runs, scene->name.c_str(), settings.frames + 1,
                 settings.width, settings.height, settings.reference ? " + ray-traced reference" : "");
    const auto started = std::chrono::steady_clock::now();
    auto result = bench::benchmarkScene(**context, scene, settings);
    if (!result) return fail(scene->name + ": " + result.error());
    std::fprintf(stderr, "bench [%zu/%zu] %s: done in %.1f s\n", run + 1, runs, scene->name.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    results.push_back(std::move(*result));
  }

  std::fputs(bench::formatTable(results).c_str(), stdout);
  for (const auto& [option, text] : {std::pair{"csv", bench::formatCsv(results)}, {"json", bench::formatJson(results)}}) {
    if (Status status = writeFile(options.text(option), text); !status) return fail(status.error());
    std::printf("wrote %s\n", options.text(option).c_str());
  }
  return 0;
}

}  // namespace specula::app
