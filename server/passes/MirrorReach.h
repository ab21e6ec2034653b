#pragma once
// Where a mirror part's reflected rays can go, summarised once per scene in the mirror's object
// space, so the frame plan can leave out reflected objects that cannot appear in the part. Every
// test here is conservative: it answers "cannot appear" only when no reflected ray can reach.
#include <cstddef>
#include <limits>
#include <optional>

#include <glm/glm.hpp>

#include "math/Bounds.h"
#include "scene/Mesh.h"
#include "scene/MirrorInfo.h"
#include "scene/MirrorParts.h"

namespace specula::passes {

struct Ball {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

struct MirrorReach {
  math::Bounds bounds;  // the part's surface
  // Every normal of the part lies within acos(normalCosine) of normalAxis; -1: normals point every way.
  glm::vec3 normalAxis{0.0f, 0.0f, 1.0f};
  float normalCosine = -1.0f;
  // A ball inside a closed convex mirror. A reflected ray leaves such a mirror in front of the
  // tangent plane where it starts, so it never enters the mirror or its shadow from the eye;
  // whatever lies in the ball's shadow (a subset of the mirror's) cannot appear in it.
  std::optional<Ball> inscribed;
  // The largest radius of curvature over the part (object space): how far a reflection point moves
  // on it for a turn of its normal, so how far a reflection moves for an error in its direction.
  // Infinite where the part is flat anywhere (an edge whose corners' normals agree).
  float largestCurvatureRadius = std::numeric_limits<float>::infinity();

  // Part `part` of a mesh mirror (`parts` from scene::MirrorParts::of on the same mesh); a closed
  // convex mesh also gets its inscribed ball.
  static MirrorReach ofMeshPart(const scene::Mesh& mesh, const scene::MirrorParts& parts, std::size_t part,
                                bool closedConvex);
  // An exact quadric: its bounds and the ball of its smallest radius.
  static MirrorReach ofQuadric(const scene::AnalyticShape& shape);
};

// Whether anything inside the world-space box `object` can be reflected by the part placed by
// `mirrorToWorld` and seen from `eye`: false only when it certainly cannot, because the object lies
// behind every tangent plane of the part, or in the eye's shadow of the part's inscribed ball.
bool canAppearIn(const MirrorReach& reach, const glm::mat4& mirrorToWorld, const math::Bounds& object,
                 const glm::vec3& eye);

// The part's largest radius of curvature in world units: infinite unless `mirrorToWorld` keeps angles.
float worldCurvatureRadius(const MirrorReach& reach, const glm::mat4& mirrorToWorld);

// Whether the eye can see the part's front at all: false when it lies behind every tangent plane.
bool facesEye(const MirrorReach& reach, const glm::mat4& mirrorToWorld, const glm::vec3& eye);

}  // namespace specula::passes
