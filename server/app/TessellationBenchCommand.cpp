// `specula bench tessellation`: every tessellation setting's cost and accuracy at one pose, per scene.
#include <algorithm>
#include <cstdio>

#include "base/CommandLine.h"
#include "app/BenchCommands.h"
#include "app/BenchScenes.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "bench/TessellationBenchmark.h"
#include "bench/TessellationReport.h"

namespace specula::app {

namespace {

CommandLine tessellationBenchOptions() {
  return CommandLine(
      "specula bench tessellation [options]",
      "Measures every tessellation setting on each scene at one pose: none; full tessellation at levels 1-5;\n"
      "crack-free adaptive with Szabo's angle metric (0.1 ... 0.001) and the pixel metric (2, 1, 0.5 px) at\n"
      "level 5. For each: triangles and vertices drawn, reflection searches (scene vertices and new edge\n"
      "midpoints), median "
      "frame and tessellation-pass time, and PSNR, SSIM and mirror mismatch against the ray-traced reference.\n"
      "Then names, per scene, the adaptive setting with the fewest vertices that is as accurate as full level 4.",
      {
          {"scenes", "LIST", "comma-separated built-in scene names or JSON scene files",
           "quad,teapot-table,checker-sphere,kitchen"},
          {"size", "WxH", "frame size in pixels", "640x480"},
          {"frames", "N", "timed frames per setting, after a warm-up frame", "3"},
          {"time", "SECONDS", "scene time of the pose measured", "0"},
          {"csv", "FILE", "CSV output, one row per scene and setting", "tessellation.csv"},
          {"json", "FILE", "JSON output", "tessellation.json"},
          glOption(),
      });
}

}  // namespace

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
    auto result = bench::benchmarkTessellation(
        **context, (*scenes)[i], settings, sweep, [&](std::size_t index, const std::string& setting) {
          std::fprintf(stderr, "bench tessellation [%zu/%zu] %s: [%zu/%zu] %s\n", i + 1, scenes->size(), name.c_str(),
                       index + 1, sweep.size(), setting.c_str());
        });
    if (!result) return fail(name + ": " + result.error());
    const auto best = bench::cheapestMatchingFullLevel4(*result);
    const auto full = std::find_if(result->begin(), result->end(), [](const auto& row) {
      return row.tessellation.threshold == 0.0f && row.tessellation.maxLevel == 4;
    });
    char line[256];
    if (best && full != result->end())
      std::snprintf(line, sizeof line,
                    "%s: full level 4 has mismatch %.4f with %u vertices; %s matches it with %u (%.0f %%)\n",
                    name.c_str(), full->mirrorMismatch, full->vertices(), best->setting.c_str(), best->vertices(),
                    100.0 * best->vertices() / std::max(1u, full->vertices()));
    else std::snprintf(line, sizeof line, "%s: no adaptive setting is as accurate as full level 4\n", name.c_str());
    goals += line;
    rows.insert(rows.end(), result->begin(), result->end());
  }
  std::fputs(bench::formatTessellationTable(rows).c_str(), stdout);
  std::fputs(goals.c_str(), stdout);
  for (const auto& [option, text] :
       {std::pair{"csv", bench::formatTessellationCsv(rows)}, {"json", bench::formatTessellationJson(rows)}}) {
    if (Status status = writeFile(options.text(option), text); !status) return fail(status.error());
    std::printf("wrote %s\n", options.text(option).c_str());
  }
  return 0;
}

}  // namespace specula::app
