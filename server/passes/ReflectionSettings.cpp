#include "passes/ReflectionSettings.h"

#include <cstdio>

namespace specula::passes {

std::string describeTessellation(const TessellationSettings& settings) {
  if (settings.mode == TessellationMode::None || settings.maxLevel == 0) return "none";
  char text[96];
  std::snprintf(text, sizeof text, "%s %s >= %g level %d",
                settings.mode == TessellationMode::Paper ? "paper" : "crack-free",
                settings.metric == TessellationMetric::Pixels ? "pixels" : "angle", settings.threshold,
                settings.maxLevel);
  return text;
}

}  // namespace specula::passes
