// `specula bench`: every method's cost and accuracy on the built-in scenes, as a table, CSV and JSON.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/GlSetup.h"
#include "app/SceneSource.h"
#include "bench/BenchReport.h"
#include "bench/SceneBenchmark.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

namespace {

constexpr int kMaxBenchSide = 4096;
constexpr int kMaxFrames = 10000;

CommandLine benchOptions() {
  return CommandLine(
      "specula bench [--scenes LIST] [--size WxH] [--frames N] [--cold-size WxH|none] [--no-reference] "
      "[--csv FILE] [--json FILE] [--gl BACKEND]",
      "Measures each scene along its own animation at 60 frames per second: median time per pass (after a\n"
      "cold first frame, reported apart because it includes shader compilation), search steps with\n"
      "frame-to-frame coherence and from a cold start, reflection-point error in pixels against the exact\n"
      "sphere solver (scenes with an analytic sphere mirror), and the last frame against the ray-traced\n"
      "reference (PSNR, SSIM, share of mismatched mirror pixels, ray-tracing time).\n"
      "Prints a table and writes the same numbers as CSV and JSON.",
      {
          {"scenes", "LIST", "comma-separated built-in scene names or JSON scene files", "all built-in scenes"},
          {"size", "WxH", "frame size in pixels", "640x480"},
          {"frames", "N", "warm frames measured after the cold one", "60"},
          {"cold-size", "WxH|none", "size of the extra cold-start frame (steps only)", "1280x720"},
          {"no-reference", "", "skip the ray-traced reference (PSNR, SSIM, ray-tracing time)", ""},
          {"csv", "FILE", "CSV output, one row per scene", "bench.csv"},
          {"json", "FILE", "JSON output", "bench.json"},
          glOption(),
      });
}

int fail(const std::string& message) {
  std::cerr << "specula bench: " << message << "\n";
  return 1;
}

std::vector<std::string> sceneList(const CommandLine& options) {
  std::vector<std::string> names;
  if (!options.has("scenes")) {
    for (std::string_view name : scene::builtinSceneNames()) names.emplace_back(name);
    return names;
  }
  std::stringstream list(options.text("scenes"));
  for (std::string name; std::getline(list, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

std::string unwritable(const std::string& path) { return "could not write '" + path + "': check the folder exists and is writable"; }

// Opening for append creates a missing file but keeps an earlier run's results until the new ones exist.
Status checkWritable(const std::string& path) {
  if (!std::ofstream(path, std::ios::binary | std::ios::app)) return Error{unwritable(path)};
  return {};
}

Status writeFile(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  if (!file) return Error{unwritable(path)};
  return {};
}

}  // namespace

int runBench(std::span<const std::string> arguments) {
  CommandLine options = benchOptions();
  if (Status status = options.parse(arguments); !status) return fail(status.error());
  if (options.helpRequested()) {
    std::cout << options.help();
    return 0;
  }
  bench::BenchOptions settings;
  auto size = options.size("size", kMaxBenchSide);
  auto frames = options.integer("frames", 1, kMaxFrames);
  if (!size) return fail(size.error());
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  if (!frames) return fail(frames.error());
  std::tie(settings.width, settings.height) = *size;
  settings.frames = *frames;
  if (options.text("cold-size") == "none") {
    settings.coldWidth = settings.coldHeight = 0;
  } else {
    auto coldSize = options.size("cold-size", kMaxBenchSide);
    if (!coldSize) return fail(coldSize.error());
    std::tie(settings.coldWidth, settings.coldHeight) = *coldSize;
  }
  settings.reference = !options.has("no-reference");
  const std::vector<std::string> names = sceneList(options);
  if (names.empty()) return fail("--scenes names no scene");

  // Check outputs and load every scene before the long part, so a typo fails at once.
  for (const char* output : {"csv", "json"})
    if (Status status = checkWritable(options.text(output)); !status) return fail(status.error());
  std::vector<std::shared_ptr<const scene::Scene>> scenes;
  for (const std::string& name : names) {
    auto loaded = loadScene(name);
    if (!loaded) return fail(loaded.error());
    scenes.push_back(*loaded);
  }
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  std::vector<bench::SceneBenchResult> results;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::fprintf(stderr, "bench [%zu/%zu] %s: %d frames at %dx%d%s ...\n", i + 1, scenes.size(), scenes[i]->name.c_str(),
                 settings.frames + 1, settings.width, settings.height, settings.reference ? " + ray-traced reference" : "");
    const auto started = std::chrono::steady_clock::now();
    auto result = bench::benchmarkScene(**context, scenes[i], settings);
    if (!result) return fail(scenes[i]->name + ": " + result.error());
    std::fprintf(stderr, "bench [%zu/%zu] %s: done in %.1f s\n", i + 1, scenes.size(), scenes[i]->name.c_str(),
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
