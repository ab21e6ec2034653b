#pragma once
// The frame graph as plain data: which passes run and which mirrors they serve, decided per frame
// from what the camera sees, so a frame without a visible mirror runs no reflection pass at all.
#include <optional>
#include <vector>

#include "math/Bounds.h"
#include "math/Camera.h"
#include "passes/FrameGraph.h"
#include "passes/ReflectionSettings.h"
#include "passes/ReflectionSlots.h"
#include "scene/ScenePose.h"

namespace specula::passes {

// How a planned mirror part finds what it reflects.
enum class PartMethod {
  VirtualObjects,  // search every reflected vertex, tessellate, rasterize the virtual objects
  RayCast,         // cast each of its pixels' reflected rays against the objects' meshes
  OwnColour,       // nothing to reflect, or smaller on screen than the error budget: its colour and the environment it
                   // reflects
  EnvironmentMap,  // everything it reflects is far: a cube map from its centre, ray-cast where that is off by more than
                   // the budget
};

// "virtual-objects", "ray-cast", "own-colour" or "environment-map", as render, bench and the protocol name them.
const char* partMethodName(PartMethod method);

// A ray-cast part's tile classification: object tiles cast on, of objects × the part's tiles (all
// `possible` where the part was not classified).
struct CastTileCount {
  std::size_t listed = 0, possible = 0;
};

// What a mirror part's reflection costs by each method, in milliseconds.
struct PartCost {
  double search = 0.0;   // search, tessellation and virtual objects
  double rayCast = 0.0;  // a cast per pixel and reflected object
};

// The cost model behind RayCastRule::WhenCheaper, for a part covering about `pixels` frame pixels,
// in milliseconds on the llvmpipe it was fitted to.
PartCost predictPartCost(double pixels, const std::vector<const ReflectionSlotRange*>& reflected);

// Per-device multipliers of predictPartCost()'s milliseconds, learnt from frames rendered there
// (passes::MeasuredCosts); 1 is the fit itself.
struct CostRates {
  double search = 1.0, rayCast = 1.0;
};

// A mirror part whose reflection is drawn this frame, and the reflected objects that can appear in it.
struct PlannedMirror {
  const MirrorSlots* slots = nullptr;
  PartMethod method = PartMethod::VirtualObjects;
  double projectedPixels = 0.0;  // the mirror's, about (projectedPixels()): what the method was chosen by
  std::vector<const ReflectionSlotRange*> reflected;
  // Per entry of `reflected`: whether tessellation may split it; one whose every edge's image stays
  // shorter than the threshold (edgesStayUnsplit) is drawn from its mesh without a round.
  std::vector<bool> tessellated;
  PartCost fittedCost;  // of the objects in `reflected`, by predictPartCost() (llvmpipe milliseconds)
  PartCost cost;        // the same on this device (fittedCost × CostRates): what chose between searching and casting
  bool facesAway = false;  // the eye is behind every tangent plane of the part: nothing is searched
  std::size_t culledObjects = 0, culledVertices = 0;  // left out: behind the part or in its shadow
  // Left out because their image in this convex part, or the whole part (OwnColour), is smaller on
  // screen than the error budget.
  std::size_t belowBudgetObjects = 0, belowBudgetVertices = 0;
  // EnvironmentMap: how far its cube-map lookup moves a reflection, in pixels at one metre from the
  // eye and at normal incidence; a pixel at distance z with incidence cosine c is off by reach / (c z).
  float environmentReach = 0.0f;
};

struct FramePlan {
  std::vector<PassId> passes;          // in execution order, none whose output nothing reads
  FrameNeeds needs;                    // what decides some passes' reads (FrameGraph)
  std::vector<PlannedMirror> mirrors;  // visible mirror parts, a mirror's parts in a row
  bool search = false;                 // some part is drawn as virtual objects: the search runs
  bool tessellate = false;             // virtual objects come from the tessellation pass
  // The settings' precision, unless RGBA16F cannot place a visible mirror's texels (far from the origin).
  GBufferPrecision gbufferPrecision = GBufferPrecision::Float32;
};

// Whether half floats resolve positions on a mirror with these world bounds finely enough for the
// search: their spacing at the mirror's largest coordinate must stay under ~1/100 of its radius.
bool halfFloatsResolve(const math::Bounds& mirrorBounds);

// worldBounds: one box per scene object at this frame's pose. With settings.plan Needed, a mirror
// out of the frustum is left out, and so is a reflected object that cannot appear in a part
// (passes::canAppearIn); a part is ray-cast by settings.rayCast (by default where predictPartCost()
// scaled by `rates` says it is cheaper; with `explore`, every part the cost decides for takes that
// method, to measure it). Everything keeps every mirror and object and searches them all.
FramePlan planFrame(const ReflectionSlots& slots, const scene::ScenePose& pose,
                    const std::vector<math::Bounds>& worldBounds, glm::ivec2 frameSize,
                    const ReflectionSettings& settings, const CostRates& rates = {},
                    std::optional<PartMethod> explore = std::nullopt);

// Frame pixels the box's enclosing sphere covers, about (all of them when the eye is inside it).
double projectedPixels(const math::Bounds& bounds, const math::Camera& camera, glm::ivec2 frameSize);

// The environment map's reach (PlannedMirror::environmentReach) for a mirror inside `mirror` with
// largest radius of curvature `curvatureRadius` (world) whose reflected objects are all at least
// `nearestObject` from the mirror's centre, looked up in cube faces of `faceSize` texels: the
// capture point is up to 2 radii from the true reflection point (parallax), a texel off in
// direction, and a direction error turns into a move on the mirror of curvature radius / 2 per
// radian (divided by the incidence cosine across the plane of incidence). Infinite when no bound
// holds (objects within three mirror radii, a flat mirror).
double environmentMapReach(const math::Bounds& mirror, double curvatureRadius, double nearestObject,
                           const math::Camera& camera, glm::ivec2 frameSize, int faceSize);

// An upper bound on the diameter in frame pixels of any image of `object` in a convex mirror part
// inside `mirror` (world boxes), seen from `eye`: a flat mirror shows an object at least as far as
// the eye–mirror–object path, and a convex one shrinks it further; off the view axis pixels per
// radian grow (1 / cos²), and no image is larger than the mirror as drawn. Infinite when the eye is
// inside the mirror's bounds.
// `featureRadius`: the bound for a ball of that radius anywhere in `object` instead (an edge).
double convexImageDiameterPixels(const math::Bounds& mirror, const math::Bounds& object, const math::Camera& camera,
                                 glm::ivec2 frameSize, std::optional<double> featureRadius = std::nullopt);

// Whether crack-free pixel tessellation (settings) has nothing to correct on an object inside
// `object` whose longest edge is `longestEdge` (world) in a convex part inside `mirror`: the image
// of each of its triangles is smaller than the threshold (convexImageDiameterPixels), so its straight
// virtual triangle is within the threshold of the curved image, and no edge is long beside the mirror.
bool edgesStayUnsplit(const math::Bounds& mirror, const math::Bounds& object, double longestEdge,
                      const math::Camera& camera, glm::ivec2 frameSize, const TessellationSettings& settings);

// Whether a world-space box can be seen through the camera's frustum widened by `margin`.
bool boundsInFrustum(const math::Bounds& bounds, const math::Camera& camera, float aspect, float margin);

}  // namespace specula::passes
