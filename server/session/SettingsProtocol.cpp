#include "session/SettingsProtocol.h"

#include <algorithm>
#include <cmath>

#include "math/SamplePattern.h"

namespace specula::session {

v1::RenderSettings settingsToProto(const SessionSettings& settings) {
  v1::RenderSettings out;
  out.set_method(settings.reflection.method == passes::ReflectionMethod::Search ? v1::SEARCH : v1::NONE);
  const passes::TessellationSettings& t = settings.reflection.tessellation;
  out.set_tessellation(t.mode == passes::TessellationMode::None    ? v1::TESSELLATION_NONE
                       : t.mode == passes::TessellationMode::Paper ? v1::TESSELLATION_PAPER
                                                                   : v1::TESSELLATION_CRACK_FREE);
  out.set_metric(t.metric == passes::TessellationMetric::Pixels ? v1::METRIC_PIXELS : v1::METRIC_ANGLE);
  out.set_threshold(t.threshold);
  out.set_level(t.maxLevel == 0 ? -1 : t.maxLevel);
  out.set_error_budget_px(settings.reflection.errorBudgetPixels == 0.0f ? -1.0f : settings.reflection.errorBudgetPixels);
  out.set_resolution_scale(settings.resolutionScale);
  out.set_jpeg_quality(static_cast<std::uint32_t>(settings.jpegQuality));
  out.set_interactive_quality(static_cast<std::uint32_t>(settings.interactiveQuality));
  out.set_still_samples(static_cast<std::uint32_t>(settings.stillSamples));
  out.set_interactive_samples(static_cast<std::uint32_t>(settings.interactiveSamples));
  out.set_plan(settings.reflection.plan == passes::PlanScope::Everything ? v1::PLAN_EVERYTHING : v1::PLAN_NEEDED);
  switch (settings.reflection.search) {
    case passes::SearchStrategy::Crosshair: out.set_search(v1::SEARCH_CROSSHAIR); break;
    case passes::SearchStrategy::Hierarchy: out.set_search(v1::SEARCH_HIERARCHY); break;
    case passes::SearchStrategy::ExplosionMap:
      out.set_search(settings.reflection.explosionRefine ? v1::SEARCH_EXPLOSION_MAP_REFINED : v1::SEARCH_EXPLOSION_MAP);
      break;
  }
  switch (settings.reflection.rayCast) {
    case passes::RayCastRule::WhenCheaper: out.set_ray_cast(v1::RAY_CAST_CHEAPER); break;
    case passes::RayCastRule::Never: out.set_ray_cast(v1::RAY_CAST_NEVER); break;
    case passes::RayCastRule::Always: out.set_ray_cast(v1::RAY_CAST_ALWAYS); break;
  }
  out.set_explosion_map_size(static_cast<std::uint32_t>(settings.reflection.explosionMapSize));
  out.set_virtual_pixels(settings.reflection.virtualPixels == passes::VirtualPixels::AsPlaced ? v1::PIXELS_AS_PLACED : v1::PIXELS_EXACT_HIT);
  out.set_extrusions(settings.reflection.solveExtrusions ? v1::EXTRUSIONS_SOLVE : v1::EXTRUSIONS_SEARCH);
  return out;
}

Status applySettingsUpdate(const v1::RenderSettings& update, SessionSettings& current) {
  SessionSettings settings = current;
  passes::TessellationSettings& t = settings.reflection.tessellation;
  switch (update.method()) {
    case v1::SEARCH: settings.reflection.method = passes::ReflectionMethod::Search; break;
    case v1::NONE: settings.reflection.method = passes::ReflectionMethod::None; break;
    case v1::METHOD_UNSPECIFIED: break;
    default: return Error{"settings: unknown method"};
  }
  switch (update.tessellation()) {
    case v1::TESSELLATION_NONE: t.mode = passes::TessellationMode::None; break;
    case v1::TESSELLATION_PAPER: t.mode = passes::TessellationMode::Paper; break;
    case v1::TESSELLATION_CRACK_FREE: t.mode = passes::TessellationMode::CrackFree; break;
    case v1::TESSELLATION_UNSPECIFIED: break;
    default: return Error{"settings: unknown tessellation mode"};
  }
  switch (update.plan()) {
    case v1::PLAN_NEEDED: settings.reflection.plan = passes::PlanScope::Needed; break;
    case v1::PLAN_EVERYTHING: settings.reflection.plan = passes::PlanScope::Everything; break;
    case v1::PLAN_UNSPECIFIED: break;
    default: return Error{"settings: unknown plan scope"};
  }
  switch (update.search()) {
    case v1::SEARCH_CROSSHAIR: settings.reflection.search = passes::SearchStrategy::Crosshair; break;
    case v1::SEARCH_HIERARCHY: settings.reflection.search = passes::SearchStrategy::Hierarchy; break;
    case v1::SEARCH_EXPLOSION_MAP:
    case v1::SEARCH_EXPLOSION_MAP_REFINED:
      settings.reflection.search = passes::SearchStrategy::ExplosionMap;
      settings.reflection.explosionRefine = update.search() == v1::SEARCH_EXPLOSION_MAP_REFINED;
      break;
    case v1::SEARCH_UNSPECIFIED: break;
    default: return Error{"settings: unknown search strategy"};
  }
  // A search the client names is what runs, not a ray cast the cost model prefers.
  if (update.search() != v1::SEARCH_UNSPECIFIED) settings.reflection.rayCast = passes::RayCastRule::Never;
  switch (update.ray_cast()) {
    case v1::RAY_CAST_CHEAPER: settings.reflection.rayCast = passes::RayCastRule::WhenCheaper; break;
    case v1::RAY_CAST_NEVER: settings.reflection.rayCast = passes::RayCastRule::Never; break;
    case v1::RAY_CAST_ALWAYS: settings.reflection.rayCast = passes::RayCastRule::Always; break;
    case v1::RAY_CAST_UNSPECIFIED: break;
    default: return Error{"settings: unknown ray_cast rule"};
  }
  if (update.explosion_map_size() != 0) {
    if (update.explosion_map_size() < static_cast<std::uint32_t>(passes::kMinExplosionMapSize) ||
        update.explosion_map_size() > static_cast<std::uint32_t>(passes::kMaxExplosionMapSize))
      return Error{"settings: explosion_map_size must be in [" + std::to_string(passes::kMinExplosionMapSize) + ", " +
                   std::to_string(passes::kMaxExplosionMapSize) + "]"};
    settings.reflection.explosionMapSize = static_cast<int>(update.explosion_map_size());
  }
  switch (update.virtual_pixels()) {
    case v1::PIXELS_EXACT_HIT: settings.reflection.virtualPixels = passes::VirtualPixels::ExactHit; break;
    case v1::PIXELS_AS_PLACED: settings.reflection.virtualPixels = passes::VirtualPixels::AsPlaced; break;
    case v1::PIXELS_UNSPECIFIED: break;
    default: return Error{"settings: unknown virtual pixels"};
  }
  switch (update.extrusions()) {
    case v1::EXTRUSIONS_SOLVE: settings.reflection.solveExtrusions = true; break;
    case v1::EXTRUSIONS_SEARCH: settings.reflection.solveExtrusions = false; break;
    case v1::EXTRUSIONS_UNSPECIFIED: break;
    default: return Error{"settings: unknown extrusions"};
  }
  switch (update.metric()) {
    case v1::METRIC_PIXELS: t.metric = passes::TessellationMetric::Pixels; break;
    case v1::METRIC_ANGLE: t.metric = passes::TessellationMetric::Angle; break;
    case v1::METRIC_UNSPECIFIED: break;
    default: return Error{"settings: unknown tessellation metric"};
  }
  if (update.threshold() != 0.0f) {
    if (!std::isfinite(update.threshold()) || update.threshold() < 0.0f || update.threshold() > 1e4f)
      return Error{"settings: threshold must be in (0, 1e4]"};
    t.threshold = update.threshold();
  }
  if (update.level() != 0) {
    if (update.level() < -1 || update.level() > passes::kMaxTessellationLevel)
      return Error{"settings: level must be 0.." + std::to_string(passes::kMaxTessellationLevel) + " (-1 for 0)"};
    t.maxLevel = std::max(0, update.level());
  }
  if (update.error_budget_px() != 0.0f) {
    const float budget = update.error_budget_px() == -1.0f ? 0.0f : update.error_budget_px();
    if (!(budget >= 0.0f && budget <= passes::kMaxErrorBudgetPixels)) return Error{"settings: error_budget_px must be in [0, 16] (-1 for 0)"};
    settings.reflection.errorBudgetPixels = budget;
  }
  if (update.resolution_scale() != 0.0f) {
    if (!std::isfinite(update.resolution_scale()) || update.resolution_scale() < 0.05f || update.resolution_scale() > 1.0f)
      return Error{"settings: resolution_scale must be in [0.05, 1]"};
    settings.resolutionScale = update.resolution_scale();
  }
  for (auto [value, field] : {std::pair{update.jpeg_quality(), &settings.jpegQuality},
                              {update.interactive_quality(), &settings.interactiveQuality}}) {
    if (value == 0) continue;
    if (value > 100) return Error{"settings: JPEG qualities must be 1..100"};
    *field = static_cast<int>(value);
  }
  for (auto [value, field] : {std::pair{update.still_samples(), &settings.stillSamples},
                              {update.interactive_samples(), &settings.interactiveSamples}}) {
    if (value == 0) continue;
    if (value > 16 || math::sampleCountProblem(static_cast<int>(value))) return Error{"settings: samples must be 1, 2, 4, 8 or 16"};
    *field = static_cast<int>(value);
  }
  current = settings;
  return {};
}

}  // namespace specula::session
