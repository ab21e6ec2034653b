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
  std::snprintf(text, sizeof text, "%s %s >= %g level %d",
                settings.mode == TessellationMode::Paper ? "paper" : "crack-free",
                settings.metric == TessellationMetric::Pixels ? "pixels" : "angle", settings.threshold,
                settings.maxLevel);
  return text;
}

std::optional<std::string> reflectionSettingsProblem(const ReflectionSettings& settings) {
  if (!(settings.gbufferMargin >= 0.0f && settings.gbufferMargin <= 1.0f)) return "G-buffer margin must lie in [0, 1]";
  if (!(settings.gbufferScale >= kMinGBufferScale && settings.gbufferScale <= kMaxGBufferScale)) {
    char text[96];
    std::snprintf(text, sizeof text, "G-buffer scale must lie in [%g, %g] texels per pixel", kMinGBufferScale, kMaxGBufferScale);
    return text;
  }
  if (settings.environmentMapSize < kMinEnvironmentMapSize || settings.environmentMapSize > kMaxEnvironmentMapSize)
    return "environment map size must lie in [" + std::to_string(kMinEnvironmentMapSize) + ", " +
           std::to_string(kMaxEnvironmentMapSize) + "] texels per cube face";
  if (!(settings.errorBudgetPixels >= 0.0f && settings.errorBudgetPixels <= kMaxErrorBudgetPixels)) {
    char text[96];
    std::snprintf(text, sizeof text, "the error budget must lie in [0, %g] pixels", kMaxErrorBudgetPixels);
    return text;
  }
  if (settings.explosionMapSize < kMinExplosionMapSize || settings.explosionMapSize > kMaxExplosionMapSize)
    return "explosion map size must lie in [" + std::to_string(kMinExplosionMapSize) + ", " + std::to_string(kMaxExplosionMapSize) +
           "] texels per side";
  if (settings.tessellation.maxLevel < 0 || settings.tessellation.maxLevel > kMaxTessellationLevel)
    return "the tessellation level must lie in [0, " + std::to_string(kMaxTessellationLevel) + "]";
  if (settings.maxWalkSteps < 1) return "the search needs at least one step per climb";
  return std::nullopt;
}

}  // namespace specula::passes
