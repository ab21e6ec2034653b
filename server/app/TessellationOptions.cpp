#include "app/TessellationOptions.h"

#include <cstdio>

namespace specula::app {

namespace {
constexpr int kMaxLevel = 8;  // 4^8 = 65 536 triangles from one: the buffer cap stops it anyway
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
  auto level = options.integer("level", 0, kMaxLevel);
  if (!level) return Error{level.error()};
  settings.maxLevel = *level;
  return settings;
}

}  // namespace specula::app
