#include "app/ReflectionOptions.h"

#include <cstdio>

#include "math/SamplePattern.h"

namespace specula::app {

namespace {
// Without --threshold: the settings' default for pixels; for angles one as fine (checker-sphere,
// `specula bench tessellation`).
constexpr float kDefaultAngleThreshold = 0.003f;
}

std::vector<OptionSpec> tessellationOptions() {
  const passes::TessellationSettings defaults;
  char threshold[64];
  std::snprintf(threshold, sizeof threshold, "%g px; %g for angle", defaults.threshold, kDefaultAngleThreshold);
  return {
      {"tessellation", "MODE", "none | paper (Szabo: worst edge splits 1->4) | crack-free (edge by edge)", "crack-free"},
      {"metric", "METRIC", "pixels (midpoint off its true reflection) | angle (Szabo's 1-(N.b+1)/2)", "pixels"},
      {"threshold", "X", "split an edge whose error is at least X (px, or 0..1 for angle; 0 = full)",
       threshold},
      {"level", "N", "at most N rounds of splitting: 4^N triangles per original at most", std::to_string(defaults.maxLevel)},
  };
}

Result<passes::TessellationSettings> parseTessellationOptions(const CommandLine& options) {
  passes::TessellationSettings settings;
  const std::string mode = options.text("tessellation");
  if (mode == "none") settings.mode = passes::TessellationMode::None;
  else if (mode == "paper") settings.mode = passes::TessellationMode::Paper;
  else if (mode == "crack-free") settings.mode = passes::TessellationMode::CrackFree;
  else return Error{"--tessellation expects none, paper or crack-free, got '" + mode + "'"};
  const std::string metric = options.text("metric");
  if (metric == "pixels") settings.metric = passes::TessellationMetric::Pixels;
  else if (metric == "angle") settings.metric = passes::TessellationMetric::Angle;
  else return Error{"--metric expects pixels or angle, got '" + metric + "'"};
  if (options.has("threshold")) {
    auto threshold = options.number("threshold");
    if (!threshold || *threshold < 0.0 || *threshold > 1e6)
      return Error{"--threshold expects a number >= 0 (pixels, or 0..1 for --metric angle), got '" + options.text("threshold") + "'"};
    settings.threshold = static_cast<float>(*threshold);
  } else if (settings.metric == passes::TessellationMetric::Angle) {
    settings.threshold = kDefaultAngleThreshold;
  }
  auto level = options.integer("level", 0, passes::kMaxTessellationLevel);
  if (!level) return Error{level.error()};
  settings.maxLevel = *level;
  return settings;
}

std::vector<OptionSpec> searchOptions() {
  const passes::ReflectionSettings defaults;
  return {
      {"search", "HOW",
       "crosshair (Estalella: climb 3x3 windows from last frame's texel) | hierarchy (Szabo: down bounding spheres and "
       "cones of the mirror's reflected rays) | explosion-map (Ofek & Rappoport: look up near and far maps of the "
       "mirror's reflected-ray directions; no search)",
       "crosshair"},
      {"explosion-map-size", "N",
       "explosion-map side in texels, " + std::to_string(passes::kMinExplosionMapSize) + " to " +
           std::to_string(passes::kMaxExplosionMapSize),
       std::to_string(defaults.explosionMapSize)},
      {"explosion-refine", "on|off", "explosion-map: climb and refine from each map point with the crosshair search", "off"},
      {"explosion-placement", "HOW",
       "explosion-map: eye-ray (a vertex on the eye's ray through the reflection point the maps give) | mirror (the "
       "paper: mirrored across the maps' planes, which magnifies their error)",
       "eye-ray"},
      {"virtual-pixels", "HOW",
       "exact-hit (a virtual triangle's pixels cast their reflected rays at its object triangle) | as-placed (shaded "
       "where the triangle lies, as the papers draw; the default with --method explosion-map)",
       "exact-hit"},
      {"extrusions", "HOW",
       "mirrors declared as extrusions (cylinders): solve (Ofek & Rappoport's exact 2-D reduction, no search) | search "
       "(their meshes with --search, like any mirror)",
       "solve"},
  };
}

Status parseSearchOptions(const CommandLine& options, passes::ReflectionSettings& settings) {
  const std::string search = options.text("search");
  const std::optional<passes::SearchStrategy> strategy = passes::parseSearchStrategy(search);
  if (!strategy) return Error{"--search expects crosshair, hierarchy or explosion-map, got '" + search + "'"};
  settings.search = *strategy;
  auto size = options.integer("explosion-map-size", passes::kMinExplosionMapSize, passes::kMaxExplosionMapSize);
  if (!size) return Error{size.error()};
  settings.explosionMapSize = *size;
  const std::string refine = options.text("explosion-refine");
  if (refine != "on" && refine != "off") return Error{"--explosion-refine expects on or off, got '" + refine + "'"};
  settings.explosionRefine = refine == "on";
  const std::string placement = options.text("explosion-placement");
  if (placement != "eye-ray" && placement != "mirror")
    return Error{"--explosion-placement expects eye-ray or mirror, got '" + placement + "'"};
  settings.explosionMirrorPlacement = placement == "mirror";
  const std::string pixels = options.text("virtual-pixels");
  if (pixels == "exact-hit") settings.virtualPixels = passes::VirtualPixels::ExactHit;
  else if (pixels == "as-placed") settings.virtualPixels = passes::VirtualPixels::AsPlaced;
  else return Error{"--virtual-pixels expects exact-hit or as-placed, got '" + pixels + "'"};
  const std::string extrusions = options.text("extrusions");
  if (extrusions != "solve" && extrusions != "search")
    return Error{"--extrusions expects solve or search, got '" + extrusions + "'"};
  settings.solveExtrusions = extrusions == "solve";
  return {};
}

std::vector<OptionSpec> planOptions() {
  return {
      {"plan", "SCOPE",
       "needed (leave out mirrors out of view and objects a mirror cannot show; ray-cast mirrors where that is cheaper) | "
       "everything (planner off)",
       "needed"},
      {"ray-cast", "WHEN",
       "cheaper (a mirror part casts its pixels' reflected rays instead of searching when the planner's cost model, "
       "measured on llvmpipe, predicts that cheaper) | never (search every part) | always; a --search or --method "
       "named on the command line is what runs: never unless given",
       "cheaper"},
      {"error-budget", "PX",
       "pixels the planner may move a reflection by: leaves out objects whose image in a convex part is smaller, shows a "
       "smaller mirror in its own colour; 0 = only exact decisions",
       "0.5"},
      {"uncovered", "FILL",
       "ray-cast (a searched mirror's pixels no virtual object covered, towards silhouettes and rims, cast their reflected "
       "rays) | background (they show the background)",
       "ray-cast"},
  };
}

Status parsePlanOptions(const CommandLine& options, passes::ReflectionSettings& settings) {
  const std::string plan = options.text("plan");
  if (plan == "needed") settings.plan = passes::PlanScope::Needed;
  else if (plan == "everything") settings.plan = passes::PlanScope::Everything;
  else return Error{"--plan expects needed or everything, got '" + plan + "'"};
  const std::string rayCast = options.text("ray-cast");
  if (rayCast == "cheaper") settings.rayCast = passes::RayCastRule::WhenCheaper;
  else if (rayCast == "never") settings.rayCast = passes::RayCastRule::Never;
  else if (rayCast == "always") settings.rayCast = passes::RayCastRule::Always;
  else return Error{"--ray-cast expects cheaper, never or always, got '" + rayCast + "'"};
  // A search or method the user names is what runs, not a ray cast the cost model prefers.
  const bool methodNamed = options.has("search") || (options.has("method") && options.text("method") == "explosion-map");
  if (methodNamed && !options.has("ray-cast")) settings.rayCast = passes::RayCastRule::Never;
  auto budget = options.number("error-budget");
  if (!budget || !(*budget >= 0.0 && *budget <= passes::kMaxErrorBudgetPixels))
    return Error{"--error-budget expects pixels in [0, 16], got '" + options.text("error-budget") + "'"};
  settings.errorBudgetPixels = static_cast<float>(*budget);
  const std::string uncovered = options.text("uncovered");
  if (uncovered == "ray-cast") settings.rayCastUncovered = true;
  else if (uncovered == "background") settings.rayCastUncovered = false;
  else return Error{"--uncovered expects ray-cast or background, got '" + uncovered + "'"};
  return {};
}

std::vector<OptionSpec> reflectionOptions() {
  const passes::ReflectionSettings defaults;
  char scale[96], faceSize[96];
  std::snprintf(scale, sizeof scale, "G-buffer texels per frame pixel along each axis, %g to %g", passes::kMinGBufferScale,
                passes::kMaxGBufferScale);
  std::snprintf(faceSize, sizeof faceSize, "cube face side in texels (environment-map), %d to %d", passes::kMinEnvironmentMapSize,
                passes::kMaxEnvironmentMapSize);
  std::vector<OptionSpec> specs = {
      {"margin", "SHARE", "G-buffer border per side as a share of the frame", "0.1"},
      {"gbuffer-scale", "X", scale, "1"},
      {"gbuffer-precision", "BITS", "G-buffer float bits: 32 (RGBA32F) or 16 (RGBA16F)", "32"},
      {"environment-size", "N", faceSize, std::to_string(defaults.environmentMapSize)},
  };
  for (OptionSpec& spec : searchOptions()) specs.push_back(std::move(spec));
  for (OptionSpec& spec : planOptions()) specs.push_back(std::move(spec));
  for (OptionSpec& spec : tessellationOptions()) specs.push_back(std::move(spec));
  return specs;
}

Result<passes::ReflectionSettings> parseReflectionOptions(const CommandLine& options) {
  passes::ReflectionSettings settings;
  auto margin = options.number("margin");
  if (!margin || *margin < 0.0 || *margin > 1.0) return Error{"--margin expects a share in [0, 1], got '" + options.text("margin") + "'"};
  settings.gbufferMargin = static_cast<float>(*margin);
  auto scale = options.number("gbuffer-scale");
  if (!scale || *scale < passes::kMinGBufferScale || *scale > passes::kMaxGBufferScale) {
    char range[64];
    std::snprintf(range, sizeof range, "from %g to %g", passes::kMinGBufferScale, passes::kMaxGBufferScale);
    return Error{"--gbuffer-scale expects texels per pixel " + std::string(range) + ", got '" + options.text("gbuffer-scale") + "'"};
  }
  settings.gbufferScale = static_cast<float>(*scale);
  const std::string precision = options.text("gbuffer-precision");
  if (precision == "32") settings.gbufferPrecision = passes::GBufferPrecision::Float32;
  else if (precision == "16") settings.gbufferPrecision = passes::GBufferPrecision::Float16;
  else return Error{"--gbuffer-precision expects 32 or 16 (bits per channel), got '" + precision + "'"};
  auto cubeFace = options.integer("environment-size", passes::kMinEnvironmentMapSize, passes::kMaxEnvironmentMapSize);
  if (!cubeFace) return Error{cubeFace.error()};
  settings.environmentMapSize = *cubeFace;
  if (Status status = parseSearchOptions(options, settings); !status) return Error{status.error()};
  if (Status status = parsePlanOptions(options, settings); !status) return Error{status.error()};
  auto tessellation = parseTessellationOptions(options);
  if (!tessellation) return Error{tessellation.error()};
  settings.tessellation = *tessellation;
  return settings;
}

OptionSpec samplesOption(int fallback, const std::string& what) { return {"samples", "N", what, std::to_string(fallback)}; }

Result<int> parseSamples(const CommandLine& options, const std::string& name) {
  auto samples = options.integer(name, 1, 16);
  if (!samples) return Error{samples.error()};
  if (auto problem = math::sampleCountProblem(*samples)) return Error{"--" + name + ": " + *problem};
  return *samples;
}

}  // namespace specula::app
