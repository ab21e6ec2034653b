#pragma once
// A mirror's exact surface in world space, for rays that must not inherit the mesh's faceting.
#include <glm/glm.hpp>
#include <optional>
#include <utility>

#include "scene/MirrorInfo.h"

namespace specula::reference {

// Where a reflected ray leaves an analytic surface, so it is not hit again at its own start.
struct SurfaceExit {
  glm::dvec3 point{0.0};  // world, on the surface
  bool outside = true;    // the ray leaves on the outward side of the surface
};

// A sphere or ellipsoid (every AnalyticShape kind is an affine image of the unit sphere) placed by an
// object-to-world matrix. All arithmetic is double precision.
class AnalyticSurface {
 public:
  AnalyticSurface(const scene::AnalyticShape& shape, const glm::mat4& objectToWorld);

  // Smallest t in (tMin, tMax) where origin + t·direction lies on the surface, or nullopt.
  std::optional<double> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                  double tMax) const;
  // The same for a ray that left this surface at `exit`: the surface is convex, so a ray leaving
  // outwards never meets it again and one leaving inwards meets it only at the far root of `exit`.
  std::optional<double> intersectLeaving(const SurfaceExit& exit, const glm::dvec3& origin, const glm::dvec3& direction,
                                         double tMin, double tMax) const;

  // origin + t·direction moved onto the surface along its radius, removing the rounding of the step.
  glm::dvec3 surfacePoint(const glm::dvec3& origin, const glm::dvec3& direction, double t) const;
  // Unit outward normal at a surface point (world).
  glm::dvec3 outwardNormal(const glm::dvec3& point) const;
  // The primitives::uvSphere parametrisation (longitude / 2π, latitude / π from the −y pole) of the
  // unit-sphere point a surface point comes from, so checkers land where they do on the mesh.
  glm::vec2 uv(const glm::dvec3& point) const;
  // World axis-aligned bounding box (low, high) of the surface.
  std::pair<glm::dvec3, glm::dvec3> bounds() const;

 private:
  glm::dvec3 toUnit(const glm::dvec3& point) const;

  glm::dmat4 unitToWorld_;
  glm::dmat4 worldToUnit_;
  glm::dmat3 normalToWorld_;
};

}  // namespace specula::reference
