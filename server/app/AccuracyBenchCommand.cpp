// `specula bench accuracy`: what each step of accuracy costs in time on one scene, with its plot.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "base/CommandLine.h"
#include "app/BenchCommands.h"
#include "app/GlSetup.h"
#include "app/OutputFiles.h"
#include "app/Plotting.h"
#include "app/SceneSource.h"
#include "bench/AccuracyBenchmark.h"
#include "bench/AccuracyReport.h"

namespace specula::app {

namespace {

CommandLine accuracyBenchOptions() {
  const bench::AccuracyBenchOptions defaults;
  return CommandLine(
      "specula bench accuracy [options]",
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
      withSceneChoice({
          {"scene", "NAME|FILE", kSceneOptionHelp, "checker-sphere"},
          {"size", "WxH", "frame size in pixels", "640x480"},
          {"poses", "N", "camera-path poses per setting, each timed and compared", std::to_string(defaults.poses)},
          {"orbit", "DEG", "how far the camera swings around its target along the path, 0 to 180",
           std::to_string(static_cast<int>(defaults.orbitDegrees))},
          {"seconds", "S", "scene time the path spans (animation), 0 to 3600", "0.5"},
          {"out", "DIR", "output folder, created if missing", "accuracy"},
          {"no-plot", "", "skip the PNG and SVG (no gnuplot needed); the .gp script is still written", ""},
          glOption(),
      }));
}

}  // namespace

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
  if (!orbit || *orbit < 0.0 || *orbit > 180.0)
    return fail("--orbit expects degrees from 0 to 180, got '" + options.text("orbit") + "'");
  if (!seconds || *seconds < 0.0 || *seconds > 3600.0)
    return fail("--seconds expects scene seconds from 0 to 3600, got '" + options.text("seconds") + "'");
  if (auto backend = parseGlOption(options.text("gl")); !backend) return fail(backend.error());
  std::tie(settings.width, settings.height) = *size;
  settings.poses = *poses;
  settings.orbitDegrees = *orbit;
  settings.seconds = *seconds;
  const bool plot = !options.has("no-plot");
  if (plot && !gnuplotAvailable())
    return fail(std::string("the plot needs gnuplot: ") + kInstallGnuplot + ", or pass --no-plot");

  // Outputs and scene first, so a typo fails before the long part.
  const std::filesystem::path folder = options.text("out");
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return fail("could not create the output folder '" + folder.string() + "': " + error.message());
  const auto output = [&](const char* extension) { return (folder / ("accuracy." + std::string(extension))).string(); };
  for (const char* extension : {"csv", "json", "md", "gp"})
    if (Status status = checkWritable(output(extension)); !status) return fail(status.error());
  auto sceneChoice = parseSceneChoice(options);
  if (!sceneChoice) return fail(sceneChoice.error());
  auto scene = loadScene(options.text("scene"), *sceneChoice);
  if (!scene) return fail(scene.error());
  auto context = openGlContext(options.text("gl"));
  if (!context) return fail(context.error());

  const std::vector<bench::AccuracySetting> sweep = bench::accuracySweep(**scene);
  // Each setting, and a ray-traced reference per pose for the scene and for every re-meshed mirror.
  const auto remeshed = static_cast<std::size_t>(
      std::count_if(sweep.begin(), sweep.end(), [](const auto& s) { return s.mirrorMesh.has_value(); }));
  const std::size_t steps = sweep.size() + (1 + remeshed) * static_cast<std::size_t>(settings.poses);
  std::size_t step = 0;
  const auto started = std::chrono::steady_clock::now();
  auto rows = bench::benchmarkAccuracy(**context, *scene, settings, sweep, [&](const std::string& what) {
    std::fprintf(stderr, "bench accuracy %s [%zu/%zu] %s (%.0f s so far)\n", (*scene)->name.c_str(), ++step, steps,
                 what.c_str(), std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  });
  if (!rows) return fail((*scene)->name + ": " + rows.error());

  char title[512];
  std::snprintf(title, sizeof title, "%s at %dx%d: %d poses, %.0f deg orbit, %s", (*scene)->name.c_str(),
                settings.width, settings.height, settings.poses, settings.orbitDegrees,
                (*context)->info().renderer.c_str());
  const std::string markdown = bench::formatAccuracyMarkdown(*rows, std::string("### ") + title);
  std::fputs(markdown.c_str(), stdout);
  for (const auto& [extension, text] :
       {std::pair{"csv", bench::formatAccuracyCsv(*rows)},
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

}  // namespace specula::app
