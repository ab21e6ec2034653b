#include "passes/ReflectionSettings.h"

#include <cstdio>

namespace specula::passes {

const char* searchStrategyName(SearchStrategy strategy) {
  switch (strategy) {
    case SearchStrategy::Crosshair: return "crosshair";
    case SearchStrategy::Hierarchy: return "hierarchy";
    case SearchStrategy::ExplosionMap: return "explosion-map";
  }
  return "?";
}

std::optional<SearchStrategy> parseSearchStrategy(std::string_view name) {
  for (SearchStrategy strategy : kSearchStrategies)
    if (name == searchStrategyName(strategy)) return strategy;
  return std::nullopt;
}

std::string describeTessellation(const TessellationSettings& settings) {
  if (settings.mode == TessellationMode::None || settings.maxLevel == 0) return "none";
  char text[96];
  std::snprintf(
      text, sizeof text, "%s %s >= %g level %d", settings.mode == TessellationMode::Paper ? "paper" : "crack-free",
      settings.metric == TessellationMetric::Pixels ? "pixels" : "angle", settings.threshold, settings.maxLevel);
  return text;
}

}  // namespace specula::passes
