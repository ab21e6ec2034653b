// `specula bench`: every method's cost and accuracy on the built-in scenes, as a table, CSV and JSON.
#include <chrono>
#include <cstdio>

#include "base/CommandLine.h"
#include "app/BenchCommands.h"
#include "app/BenchScenes.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "app/ReflectionOptions.h"
#include "app/SceneSource.h"
#include "bench/SceneBenchmark.h"
#include "bench/SceneReport.h"
#include "math/SamplePattern.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

namespace {

CommandLine benchOptions() {
  std::vector<OptionSpec> specs = {
      {"scenes", "LIST", "comma-separated built-in scene names, glTF files (.gltf, .glb) or JSON scene files",
       "all built-in scenes"},
      {"size", "WxH", "frame size in pixels", "640x480"},
      {"sizes", "LIST", "comma-separated frame sizes, each scene measured at each (instead of --size)", "--size"},
      {"frames", "N", "warm frames measured after the cold one", "60"},
      {"cold-size", "WxH|none", "size of the extra cold-start frame (steps only)", "1280x720"},
      {"no-reference", "", "skip the ray-traced reference (PSNR, SSIM, ray-tracing time)", ""},
      {"pass-timing", "HOW",
       "per-pass (each pass timed: GPU timestamps, or on llvmpipe a glFinish after each, which slows the frame) | "
       "frame "
       "(whole frames as served, no wait between passes; pass columns empty)",
       "per-pass"},
      samplesOption(
          math::kStillFrameSamples,
          "samples a pixel of the still frame compared with the ray tracer (which takes the same): 1, 2, 4, 8 or 16"),
      {"csv", "FILE", "CSV output, one row per scene", "bench.csv"},
      {"json", "FILE", "JSON output", "bench.json"},
      glOption(),
  };
  specs = withSceneChoice(std::move(specs));
  for (OptionSpec& spec : searchOptions()) specs.push_back(std::move(spec));
  for (OptionSpec& spec : planOptions()) specs.push_back(std::move(spec));
  return CommandLine(
      "specula bench [tessellation|accuracy|serve] [options]",
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

}  // namespace

int runSceneBench(std::span<const std::string> arguments) {
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
  auto sceneChoice = parseSceneChoice(options);
  if (!sceneChoice) return fail(sceneChoice.error());
  auto loaded = loadScenes(names, *sceneChoice);
  if (!loaded) return fail(loaded.error());
  const std::vector<std::shared_ptr<const scene::Scene>>& scenes = *loaded;
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  std::vector<bench::SceneBenchResult> results;
  const std::size_t runs = scenes.size() * sizes.size();
  for (std::size_t run = 0; run < runs; ++run) {
    const std::shared_ptr<const scene::Scene>& scene = scenes[run / sizes.size()];
    std::tie(settings.width, settings.height) = sizes[run % sizes.size()];
    std::fprintf(stderr, "bench [%zu/%zu] %s: %d frames at %dx%d%s ...\n", run + 1, runs, scene->name.c_str(),
                 settings.frames + 1, settings.width, settings.height,
                 settings.reference ? " + ray-traced reference" : "");
    const auto started = std::chrono::steady_clock::now();
    auto result = bench::benchmarkScene(**context, scene, settings);
    if (!result) return fail(scene->name + ": " + result.error());
    std::fprintf(stderr, "bench [%zu/%zu] %s: done in %.1f s\n", run + 1, runs, scene->name.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    results.push_back(std::move(*result));
  }

  std::fputs(bench::formatTable(results).c_str(), stdout);
  for (const auto& [option, text] :
       {std::pair{"csv", bench::formatCsv(results)}, {"json", bench::formatJson(results)}}) {
    if (Status status = writeFile(options.text(option), text); !status) return fail(status.error());
    std::printf("wrote %s\n", options.text(option).c_str());
  }
  return 0;
}

}  // namespace specula::app
