#include "passes/ReflectionSettingsSchema.h"

#include <algorithm>
#include <type_traits>

namespace specula::passes {

namespace {

// Angle errors run from 0 to 1, so the pixel threshold's default would never split an edge.
constexpr float kDefaultAngleThreshold = 0.003f;

// Binds `info` to a member of ReflectionSettings or of its TessellationSettings. A Choice names the
// member's value for each of its choices, in order.
template <class Owner, class Field>
ReflectionSetting bind(SettingInfo info, Field Owner::*member, std::vector<Field> choiceValues = {}) {
  static constexpr auto owner = [](auto& settings) -> auto& {
    if constexpr (std::is_same_v<Owner, TessellationSettings>) return settings.tessellation;
    else return settings;
  };
  if (info.type != SettingType::Choice)
    return {std::move(info), [member](const ReflectionSettings& s) { return static_cast<double>(owner(s).*member); },
            [member](ReflectionSettings& s, double value) { owner(s).*member = static_cast<Field>(value); }};
  return {std::move(info),
          [member, choiceValues](const ReflectionSettings& s) {
            const auto found = std::find(choiceValues.begin(), choiceValues.end(), owner(s).*member);
            return static_cast<double>(found - choiceValues.begin());
          },
          [member, choiceValues](ReflectionSettings& s, double index) {
            owner(s).*member = choiceValues.at(static_cast<std::size_t>(index));
          }};
}

std::vector<ReflectionSetting> declareSettings() {
  using R = ReflectionSettings;
  using T = TessellationSettings;
  constexpr SettingType kNumber = SettingType::Number, kInteger = SettingType::Integer;
  std::vector<ReflectionSetting> settings = {
      bind(choiceSetting(
               kMethodGroup, "method", "what mirrors show",
               {{"search", "virtual objects from the screen-space reflection-point search", "SEARCH"},
                {"none", "each mirror in its own colour", "NONE"},
                {"environment-map", "a cube map from each mirror's centre, the usual engine shortcut (no parallax)",
                 "ENVIRONMENT_MAP"}},
               "method"),
           &R::method, {ReflectionMethod::Search, ReflectionMethod::None, ReflectionMethod::EnvironmentMap}),

      bind(numberSetting(kGBufferGroup, kNumber, "margin", "SHARE", "G-buffer border per side as a share of the frame",
                         0.0, 1.0),
           &R::gbufferMargin),
      bind(numberSetting(kGBufferGroup, kNumber, "gbuffer-scale", "X",
                         "G-buffer texels per frame pixel along each axis", kMinGBufferScale, kMaxGBufferScale),
           &R::gbufferScale),
      bind(choiceSetting(kGBufferGroup, "gbuffer-precision", "G-buffer float bits",
                         {{"32", "RGBA32F", ""}, {"16", "RGBA16F: half the memory; far mirrors fall back to 32", ""}}),
           &R::gbufferPrecision, {GBufferPrecision::Float32, GBufferPrecision::Float16}),
      bind(numberSetting(kGBufferGroup, kInteger, "environment-size", "N",
                         "cube face side in texels (method environment-map)", kMinEnvironmentMapSize,
                         kMaxEnvironmentMapSize),
           &R::environmentMapSize),

      bind(choiceSetting(
               kSearchGroup, "search", "how each vertex's reflection point is found",
               {{"crosshair", "Estalella: climb 3x3 windows from last frame's texel", "SEARCH_CROSSHAIR"},
                {"hierarchy", "Szabo: down bounding spheres and cones of the mirror's reflected rays",
                 "SEARCH_HIERARCHY"},
                {"explosion-map",
                 "Ofek & Rappoport: look up near and far maps of the mirror's reflected-ray directions; no search",
                 "SEARCH_EXPLOSION_MAP"}},
               "search"),
           &R::search, {SearchStrategy::Crosshair, SearchStrategy::Hierarchy, SearchStrategy::ExplosionMap}),
      bind(numberSetting(kSearchGroup, kInteger, "explosion-map-size", "N", "explosion-map side in texels",
                         kMinExplosionMapSize, kMaxExplosionMapSize, "explosion_map_size"),
           &R::explosionMapSize),
      bind(choiceSetting(kSearchGroup, "explosion-refine",
                         "explosion-map: climb and refine from each map point with the crosshair search",
                         {{"off", "", "SWITCH_OFF"}, {"on", "", "SWITCH_ON"}}, "explosion_refine"),
           &R::explosionRefine, {false, true}),
      bind(choiceSetting(
               kSearchGroup, "explosion-placement", "explosion-map: where a visible vertex is placed",
               {{"eye-ray", "on the eye's ray through the reflection point the maps give", "PLACEMENT_EYE_RAY"},
                {"mirror", "the paper: mirrored across the maps' planes, which magnifies their error",
                 "PLACEMENT_MIRROR"}},
               "explosion_placement"),
           &R::explosionMirrorPlacement, {false, true}),
      bind(choiceSetting(kSearchGroup, "virtual-pixels", "what a virtual triangle's pixels show",
                         {{"exact-hit", "each pixel casts its reflected ray at the triangle's object triangle",
                           "PIXELS_EXACT_HIT"},
                          {"as-placed", "shaded where the triangle lies, as the papers draw", "PIXELS_AS_PLACED"}},
                         "virtual_pixels"),
           &R::virtualPixels, {VirtualPixels::ExactHit, VirtualPixels::AsPlaced}),
      bind(choiceSetting(kSearchGroup, "extrusions", "mirrors declared as extrusions (cylinders)",
                         {{"solve", "Ofek & Rappoport's exact 2-D reduction, no search", "EXTRUSIONS_SOLVE"},
                          {"search", "their meshes searched like any mirror", "EXTRUSIONS_SEARCH"}},
                         "extrusions"),
           &R::solveExtrusions, {true, false}),

      bind(choiceSetting(kPlanGroup, "plan", "what the frame plan leaves out",
                         {{"needed", "mirrors out of view and objects a mirror cannot show", "PLAN_NEEDED"},
                          {"everything", "nothing: the planner off, for comparison", "PLAN_EVERYTHING"}},
                         "plan"),
           &R::plan, {PlanScope::Needed, PlanScope::Everything}),
      bind(choiceSetting(
               kPlanGroup, "ray-cast",
               "which mirror parts cast their pixels' reflected rays instead of searching; a named search runs: "
               "never unless this is named too",
               {{"cheaper", "where the planner's costs, measured on this device, say casting is cheaper",
                 "RAY_CAST_CHEAPER"},
                {"never", "search every part: the virtual-objects method alone", "RAY_CAST_NEVER"},
                {"always", "cast every part", "RAY_CAST_ALWAYS"}},
               "ray_cast"),
           &R::rayCast, {RayCastRule::WhenCheaper, RayCastRule::Never, RayCastRule::Always}),
      bind(numberSetting(
               kPlanGroup, kNumber, "error-budget", "PX",
               "pixels the planner may move a reflection by: leaves out objects whose image in a convex part is "
               "smaller, shows a smaller mirror in its own colour; 0 = only exact decisions",
               0.0, kMaxErrorBudgetPixels, "error_budget_px"),
           &R::errorBudgetPixels),
      bind(choiceSetting(kPlanGroup, "uncovered",
                         "a searched mirror's pixels no virtual object covered (silhouettes, rims)",
                         {{"ray-cast", "cast their reflected rays", "UNCOVERED_RAY_CAST"},
                          {"background", "show the environment they reflect", "UNCOVERED_BACKGROUND"}},
                         "uncovered"),
           &R::rayCastUncovered, {true, false}),

      bind(choiceSetting(
               kTessellationGroup, "tessellation", "adaptive tessellation of reflected geometry (Szabo)",
               {{"none", "virtual triangles straight between their corners' reflections", "TESSELLATION_NONE"},
                {"paper", "Szabo's loop: a triangle whose worst edge is off splits 1->4", "TESSELLATION_PAPER"},
                {"crack-free", "edge by edge, conforming patterns: no T-junctions", "TESSELLATION_CRACK_FREE"}},
               "tessellation"),
           &T::mode, {TessellationMode::None, TessellationMode::Paper, TessellationMode::CrackFree}),
      bind(choiceSetting(kTessellationGroup, "metric", "an edge's error",
                         {{"pixels", "its midpoint off its true reflection, in pixels", "METRIC_PIXELS"},
                          {"angle", "Szabo's 1-(N.b+1)/2, from 0 to 1", "METRIC_ANGLE"}},
                         "metric"),
           &T::metric, {TessellationMetric::Pixels, TessellationMetric::Angle}),
      bind(numberSetting(kTessellationGroup, kNumber, "threshold", "X",
                         "split an edge whose error is at least X (pixels, or 0..1 for angle; 0 = full)", 0.0, 1e4,
                         "threshold"),
           &T::threshold),
      bind(
          numberSetting(kTessellationGroup, kInteger, "level", "N",
                        "at most N rounds of splitting: 4^N triangles per original", 0, kMaxTessellationLevel, "level"),
          &T::maxLevel),
  };
  for (ReflectionSetting& setting : settings)
    if (setting.info.name == "threshold") setting.info.defaultText = "1 px; 0.003 for angle";
  return settings;
}

}  // namespace

const std::vector<ReflectionSetting>& reflectionSettingsSchema() {
  static const std::vector<ReflectionSetting> schema = declareSettings();
  return schema;
}

void applyImpliedSettings(ReflectionSettings& settings, const std::function<bool(std::string_view name)>& named) {
  if (named("search") && !named("ray-cast")) settings.rayCast = RayCastRule::Never;
  if (named("metric") && !named("threshold") && settings.tessellation.metric == TessellationMetric::Angle)
    settings.tessellation.threshold = kDefaultAngleThreshold;
}

std::optional<std::string> reflectionSettingsProblem(const ReflectionSettings& settings) {
  for (const ReflectionSetting& setting : reflectionSettingsSchema())
    if (auto problem = settingProblem(setting.info, setting.read(settings))) return problem;
  if (settings.maxWalkSteps < 1) return "the search needs at least one step per climb";
  return std::nullopt;
}

}  // namespace specula::passes
