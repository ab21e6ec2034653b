#include "passes/FramePlan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/gtc/constants.hpp>

#include "passes/MirrorReach.h"

namespace specula::passes {

bool boundsInFrustum(const math::Bounds& bounds, const math::Camera& camera, float aspect, float margin) {
  if (bounds.empty()) return false;
  // Sphere against the four side planes and the eye plane, in eye space.
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const glm::vec3 toCenter = bounds.center() - camera.eye;
  const float radius = bounds.radius();
  const glm::vec3 local(glm::dot(toCenter, right), glm::dot(toCenter, up), glm::dot(toCenter, forward));
  if (local.z < -radius) return false;
  const float tanY = std::tan(glm::radians(camera.fovYDegrees) * 0.5f) * (1.0f + 2.0f * margin);
  const float tanX = tanY * aspect;
  // Distance from the centre to a side plane through the eye with slope tan: (|lateral| - tan z) / sqrt(1 + tan²).
  const auto outside = [&](float lateral, float slope) {
    return (std::abs(lateral) - slope * local.z) / std::sqrt(1.0f + slope * slope) > radius;
  };
  return !outside(local.x, tanX) && !outside(local.y, tanY);
}

bool halfFloatsResolve(const math::Bounds& mirrorBounds) {
  // A half float's spacing is 2^-10 of its magnitude at worst; 2^-10 * 8 radii ~ radius / 128.
  constexpr float kReachInRadii = 8.0f;
  const glm::vec3 centre = mirrorBounds.center();
  const float largest = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)}) + mirrorBounds.radius();
  return largest <= kReachInRadii * mirrorBounds.radius();
}

namespace {

// Pixels per unit of tan(angle) off the view axis.
double focalPixels(const math::Camera& camera, glm::ivec2 frameSize) {
  return 0.5 * frameSize.y / std::tan(glm::radians(static_cast<double>(camera.fovYDegrees)) * 0.5);
}

// Radius in pixels of a sphere of `radius` seen `distance` away (distance > radius), on the view axis.
double projectedRadius(double radius, double distance, double focal) {
  return focal * std::tan(std::asin(radius / distance));
}

// How much larger in pixels than on the view axis anything seen within the mirror's bounding sphere
// can be drawn: a pixel's offset is focal * tan(angle off the axis), so pixels per radian grow as 1 /
// cos²; infinite when the sphere reaches 80° off the axis (or holds the eye).
double offAxisStretch(const math::Bounds& mirror, const math::Camera& camera) {
  const glm::dvec3 toCentre = glm::dvec3(mirror.center()) - glm::dvec3(camera.eye);
  const double distance = glm::length(toCentre);
  if (distance <= mirror.radius()) return std::numeric_limits<double>::infinity();
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
  const double angle =
      std::acos(std::clamp(glm::dot(forward, toCentre / distance), -1.0, 1.0)) + std::asin(mirror.radius() / distance);
  if (angle >= glm::radians(80.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / (std::cos(angle) * std::cos(angle));
}

// The largest distance in frame pixels between two points of the mirror as drawn: every image in it
// lies there.
double mirrorDiameterPixels(const math::Bounds& mirror, const math::Camera& camera, glm::ivec2 frameSize) {
  const double distance = glm::length(mirror.center() - camera.eye);
  if (distance <= mirror.radius()) return std::numeric_limits<double>::infinity();
  return 2.0 * projectedRadius(mirror.radius(), distance, focalPixels(camera, frameSize)) *
         offAxisStretch(mirror, camera);
}

}  // namespace

PartCost predictPartCost(double pixels, const std::vector<const ReflectionSlotRange*>& reflected) {
  // Milliseconds on llvmpipe (2 cores), fitted to `specula bench --ray-cast never` and `--ray-cast
  // always` on the built-in scenes at 320x240, 640x480 and 1280x720 (docs/frame-plan.md, "The rules").
  // Casting: one draw per reflected object over the part's pixels (fits within 30 %). Searching: a
  // share of the pyramid and the tessellation rounds' readbacks, the virtual objects' raster over
  // the part, and per reflected vertex and triangle the search, tessellation and drawing. How much
  // a mesh splits is not known before the frame. The per-triangle cost is 4x the ufo's (which fit
  // within 2x the kitchen and teapot-table): utah-teapot's body, tightly curved, splits its floor
  // so much that at the ufo's cost it was predicted 37 ms and took about 500 (3x the whole frame
  // ray-cast). Over-predicting costs less: a part is ray-cast, exact, where searching was cheaper.
  constexpr double kCastPerDraw = 0.021, kCastPerPixelAndObject = 5.1e-5;
  constexpr double kSearchPerPart = 8.0, kSearchPerPixel = 5.0e-5, kSearchPerVertex = 1.0e-3,
                   kSearchPerTriangle = 1.8e-2;
  PartCost cost;
  cost.search = kSearchPerPart + kSearchPerPixel * pixels;
  for (const ReflectionSlotRange* range : reflected) {
    cost.rayCast += kCastPerDraw + kCastPerPixelAndObject * pixels;
    cost.search += kSearchPerVertex * range->vertexCount + kSearchPerTriangle * range->triangleCount;
  }
  return cost;
}

const char* partMethodName(PartMethod method) {
  switch (method) {
    case PartMethod::VirtualObjects: return "virtual-objects";
    case PartMethod::RayCast: return "ray-cast";
    case PartMethod::OwnColour: return "own-colour";
    case PartMethod::EnvironmentMap: return "environment-map";
  }
  return "virtual-objects";
}

double projectedPixels(const math::Bounds& bounds, const math::Camera& camera, glm::ivec2 frameSize) {
  const double framePixels = static_cast<double>(frameSize.x) * static_cast<double>(frameSize.y);
  if (bounds.empty()) return 0.0;
  const double distance = glm::length(bounds.center() - camera.eye), radius = bounds.radius();
  if (distance <= radius) return framePixels;
  const double pixels = projectedRadius(radius, distance, focalPixels(camera, frameSize));
  return std::min(framePixels, glm::pi<double>() * pixels * pixels);
}

double environmentMapReach(const math::Bounds& mirror, double curvatureRadius, double nearestObject,
                           const math::Camera& camera, glm::ivec2 frameSize, int faceSize) {
  const double capture = 2.0 * mirror.radius();  // from the capture point to any point of the mirror
  if (mirror.empty() || !std::isfinite(curvatureRadius) || nearestObject <= 2.0 * capture)
    return std::numeric_limits<double>::infinity();
  const double parallax = capture / (nearestObject - capture), texel = 2.0 / faceSize;
  return focalPixels(camera, frameSize) * 0.5 * curvatureRadius * (parallax + texel);
}

double convexImageDiameterPixels(const math::Bounds& mirror, const math::Bounds& object, const math::Camera& camera,
                                 glm::ivec2 frameSize, std::optional<double> featureRadius) {
  if (mirror.empty() || object.empty()) return 0.0;
  const double eyeToMirror = glm::length(mirror.center() - camera.eye) - mirror.radius();
  const double mirrorToObject = glm::length(object.center() - mirror.center()) - mirror.radius() - object.radius();
  const double path = eyeToMirror + mirrorToObject, radius = featureRadius.value_or(object.radius());
  const double mirrorSize = mirrorDiameterPixels(mirror, camera, frameSize);
  if (eyeToMirror <= 0.0 || mirrorToObject <= 0.0 || path <= radius) return mirrorSize;
  return std::min(mirrorSize,
                  2.0 * projectedRadius(radius, path, focalPixels(camera, frameSize)) * offAxisStretch(mirror, camera));
}

bool edgesStayUnsplit(const math::Bounds& mirror, const math::Bounds& object, double longestEdge,
                      const math::Camera& camera, glm::ivec2 frameSize, const TessellationSettings& settings) {
  // Only crack-free pixel tessellation measures its error in pixels edge by edge.
  if (settings.mode != TessellationMode::CrackFree || settings.metric != TessellationMetric::Pixels ||
      !(settings.threshold > 0.0f))
    return false;
  // tessellation-classify.comp splits an edge longer than half its distance from the mirror (at
  // least the mirror's radius) whatever it shows; the nearest point of the object's box bounds that.
  const glm::vec3 centre = mirror.center();
  const float toObject = glm::length(glm::max(glm::max(object.low - centre, centre - object.high), glm::vec3(0.0f)));
  if (longestEdge > 0.5 * std::max(toObject, mirror.radius())) return false;
  // Each triangle lies in a ball of its longest edge's radius, whose image bounds both the triangle's
  // curved image and the straight virtual triangle between its corners' images.
  return convexImageDiameterPixels(mirror, object, camera, frameSize, longestEdge) < settings.threshold;
}

FramePlan planFrame(const ReflectionSlots& slots, const scene::ScenePose& pose,
                    const std::vector<math::Bounds>& worldBounds, glm::ivec2 frameSize,
                    const ReflectionSettings& settings, const CostRates& rates, std::optional<PartMethod> explore) {
  const math::Camera& camera = pose.camera;
  const float aspect = static_cast<float>(frameSize.x) / static_cast<float>(frameSize.y);
  FramePlan plan;
  plan.passes.push_back(PassId::Scene);
  if (settings.method == ReflectionMethod::None) return plan;
  const bool everything = settings.plan == PlanScope::Everything;
  for (const MirrorSlots& mirror : slots.mirrors) {
    if (!everything && !boundsInFrustum(worldBounds[mirror.mirrorObject], camera, aspect, 0.0f)) continue;
    const glm::mat4& mirrorToWorld = pose.objectToWorld[mirror.mirrorObject];
    const math::Bounds& mirrorBounds = worldBounds[mirror.mirrorObject];
    // The part's own pixels: one part of a mirror casts and searches over its share of the mirror only.
    const double pixels = projectedPixels(
        mirror.deforms ? mirrorBounds : mirror.reach.bounds.transformed(mirrorToWorld), camera, frameSize);
    const bool search = settings.method == ReflectionMethod::Search;
    PartMethod method =
        settings.method == ReflectionMethod::EnvironmentMap ? PartMethod::EnvironmentMap : PartMethod::VirtualObjects;
    // A mirror narrower than the budget moves no reflection by more than it, whatever it shows; one with
    // nothing to reflect shows the environment alone.
    if (mirror.reflected.empty() ||
        (!everything && search && mirrorDiameterPixels(mirrorBounds, camera, frameSize) < settings.errorBudgetPixels))
      method = PartMethod::OwnColour;
    // A part that faces away stays in the plan (the mirror's other parts share its stencil and
    // composite) but draws nothing.
    PlannedMirror planned{&mirror, method, pixels, {},
                          {},      {},     {},     !everything && !facesEye(mirror.reach, mirrorToWorld, camera.eye),
                          0,       0};
    for (const ReflectionSlotRange& range : mirror.reflected) {
      const math::Bounds& objectBounds = worldBounds[range.object];
      if (!everything && (planned.facesAway || !canAppearIn(mirror.reach, mirrorToWorld, objectBounds, camera.eye))) {
        ++planned.culledObjects;
        planned.culledVertices += range.vertexCount;
      } else if (method == PartMethod::OwnColour ||
                 (!everything && mirror.kind == scene::SurfaceKind::Convex &&
                  convexImageDiameterPixels(mirrorBounds, objectBounds, camera, frameSize) <
                      settings.errorBudgetPixels)) {
        ++planned.belowBudgetObjects;
        planned.belowBudgetVertices += range.vertexCount;
      } else {
        planned.reflected.push_back(&range);
      }
    }
    planned.fittedCost = predictPartCost(pixels, planned.reflected);
    planned.cost = {planned.fittedCost.search * rates.search, planned.fittedCost.rayCast * rates.rayCast};
    // A search on an open surface would pin reflection points that lie past its rim to the rim, and one on a
    // deforming surface would trust curvature classes found on its rest shape: such mirrors are cast whatever
    // the settings ask.
    if (method == PartMethod::VirtualObjects && search && (mirror.twoSided || mirror.deforms))
      method = planned.method = PartMethod::RayCast;
    if (method == PartMethod::VirtualObjects && search && !everything &&
        (settings.rayCast == RayCastRule::Always ||
         (settings.rayCast == RayCastRule::WhenCheaper &&
          (explore ? *explore == PartMethod::RayCast : planned.cost.rayCast < planned.cost.search))))
      method = planned.method = PartMethod::RayCast;
    for (const ReflectionSlotRange* range : planned.reflected) {
      const glm::mat3 linear(pose.objectToWorld[range->object]);
      const double scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
      planned.tessellated.push_back(everything || mirror.kind != scene::SurfaceKind::Convex ||
                                    !edgesStayUnsplit(mirrorBounds, worldBounds[range->object],
                                                      scale * range->longestEdge, camera, frameSize,
                                                      settings.tessellation));
    }
    // Everything it reflects far away: a cube map serves most of its pixels within the budget (those
    // seen within 60° of its normal, at least), the rest are ray-cast. One part that cannot meet its
    // own rays: the cube is captured from outside it. It replaces searching, not a small mirror's
    // ray cast, which is exact and costs per pixel, as the cube's lookup does.
    if (method == PartMethod::VirtualObjects && !everything && search && settings.errorBudgetPixels > 0.0f &&
        mirror.partCount == 1 && !mirror.seesItself && !planned.reflected.empty()) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const ReflectionSlotRange* range : planned.reflected)
        nearest = std::min(
            nearest, static_cast<double>(glm::length(worldBounds[range->object].center() - mirrorBounds.center()) -
                                         worldBounds[range->object].radius()));
      const double reach = environmentMapReach(mirrorBounds, worldCurvatureRadius(mirror.reach, mirrorToWorld), nearest,
                                               camera, frameSize, settings.environmentMapSize);
      const double eyeToMirror = glm::length(mirrorBounds.center() - camera.eye) - mirrorBounds.radius();
      if (eyeToMirror > 0.0 && reach <= 0.5 * settings.errorBudgetPixels * eyeToMirror) {
        planned.method = PartMethod::EnvironmentMap;
        planned.environmentReach = static_cast<float>(reach);
      }
    }
    plan.mirrors.push_back(std::move(planned));
  }
  if (plan.mirrors.empty()) return plan;
  plan.gbufferPrecision = settings.gbufferPrecision;
  for (const PlannedMirror& mirror : plan.mirrors)
    if (!halfFloatsResolve(worldBounds[mirror.slots->mirrorObject])) plan.gbufferPrecision = GBufferPrecision::Float32;
  if (settings.method == ReflectionMethod::EnvironmentMap) {
    plan.passes.insert(plan.passes.end(), {PassId::MirrorGBuffer, PassId::EnvironmentMap});
    return plan;
  }
  plan.passes.push_back(PassId::MirrorGBuffer);
  // Searching (and so its pyramid or ray hierarchy, and tessellation) only for parts drawn as virtual objects.
  plan.search = std::any_of(plan.mirrors.begin(), plan.mirrors.end(),
                            [](const PlannedMirror& mirror) { return mirror.method == PartMethod::VirtualObjects; });
  // A solved extrusion needs no pyramid, hierarchy or maps: only the search pass, which solves it.
  const bool strategyNeeded = std::any_of(plan.mirrors.begin(), plan.mirrors.end(), [&](const PlannedMirror& mirror) {
    return mirror.method == PartMethod::VirtualObjects && !(settings.solveExtrusions && mirror.slots->extrusion);
  });
  if (plan.search && !strategyNeeded) plan.passes.push_back(PassId::Search);
  if (strategyNeeded) switch (settings.search) {
      case SearchStrategy::Crosshair:
        plan.passes.insert(plan.passes.end(), {PassId::GBufferPyramid, PassId::Search});
        break;
      case SearchStrategy::Hierarchy:
        plan.passes.insert(plan.passes.end(), {PassId::RayHierarchy, PassId::Search});
        break;
      case SearchStrategy::ExplosionMap:
        // The refinement's climb falls back to the pyramid's cold start where the map's point is off the part.
        plan.passes.push_back(PassId::ExplosionMap);
        if (settings.explosionRefine) plan.passes.push_back(PassId::GBufferPyramid);
        plan.passes.push_back(PassId::Search);
        break;
    }
  plan.tessellate =
      plan.search && settings.tessellation.mode != TessellationMode::None && settings.tessellation.maxLevel > 0;
  if (plan.tessellate) plan.passes.push_back(PassId::Tessellation);
  plan.passes.push_back(PassId::VirtualObjects);
  // After the virtual objects: they ray-cast the pixels the cube map cannot serve.
  if (std::any_of(plan.mirrors.begin(), plan.mirrors.end(),
                  [](const PlannedMirror& mirror) { return mirror.method == PartMethod::EnvironmentMap; }))
    plan.passes.push_back(PassId::EnvironmentMap);
  plan.needs = {settings.search, settings.explosionRefine, strategyNeeded, plan.search, plan.tessellate};
  plan.passes = cullUnread(plan.passes, plan.needs);
  return plan;
}

}  // namespace specula::passes
