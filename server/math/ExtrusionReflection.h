#pragma once
// Ofek & Rappoport's (1998, §5) exact reflection points on a linear extrusion of a convex planar
// curve: project eye and vertex onto the curve's plane, find the 2-D reflection point on the curve by
// a binary search over its reflection subdivision (the cells between the reflected rays of the
// curve's points, ordered along the curve), extrude the tangent line there into a plane along the
// extrusion and mirror the vertex across it. The curves: ellipses, circles among them (cylinders).
// The GLSL twin is shaders/common/extrusion.glsl.
#include <glm/glm.hpp>
#include <optional>

namespace specula::math {

// The surface { axisPoint + a·cos t·u + b·sin t·v + h·direction }: an elliptic cylinder, unbounded
// along `direction`; u, v and direction orthonormal, radii (a, b) > 0.
struct Extrusion {
  glm::dvec3 axisPoint{0.0};
  glm::dvec3 u{1.0, 0.0, 0.0}, v{0.0, 0.0, 1.0}, direction{0.0, 1.0, 0.0};
  glm::dvec2 radii{1.0};

  // The extrusion of an ellipse of semi-axes `radii` about `axisPoint`, ⊥ `direction` (any length):
  // u is the x axis made perpendicular to the direction (the z axis where the direction is within
  // about 25° of x), v = u × direction. A vertical cylinder's profile is in (x, z).
  static Extrusion along(const glm::dvec3& axisPoint, const glm::dvec3& direction, const glm::dvec2& radii);

  // The same surface after an affine map (a scene object's transform): still an elliptic cylinder,
  // whose cross-section ⊥ the mapped direction is found from the singular values of the mapped profile.
  // nullopt when the map is singular on it.
  std::optional<Extrusion> transformed(const glm::dmat4& objectToWorld) const;

  glm::dvec3 pointAt(double t, double height) const;
  glm::dvec3 normalAt(double t) const;  // unit, outwards
};

struct SurfacePoint {
  glm::dvec3 position{0.0};
  glm::dvec3 normal{0.0};         // unit, outwards
  double profileParameter = 0.0;  // t of Extrusion::pointAt
};

// The point of the extrusion's outside whose normal bisects the directions to `eye` and `vertex`,
// visible from both. nullopt when there is none: the vertex is hidden in the shadow the eye's tangent
// planes cast behind the extrusion ("region C"), or eye or vertex is inside it or not finite.
std::optional<SurfacePoint> extrusionReflectionPoint(const Extrusion& extrusion, const glm::dvec3& eye,
                                                     const glm::dvec3& vertex);

}  // namespace specula::math
