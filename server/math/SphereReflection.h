#pragma once
// The exact reflection point on the outside of a mirror sphere (Alhazen's problem), robust where
// a closed-form quartic in floats is not: near-collinear, grazing and far configurations.
#include <glm/glm.hpp>
#include <optional>

namespace specula::math {

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
};

// The point R on the sphere whose normal bisects the directions to `eye` and to `vertex`, on the
// part of the sphere visible from both. nullopt when that part is empty (the vertex is hidden
// behind the mirror: "region C") or when eye or vertex is not outside the sphere.
// Solves the 1-D angle condition in the plane of eye, centre and vertex by bisection on a bracket
// that always holds a sign change, so it cannot diverge or produce NaN.
std::optional<glm::dvec3> sphereReflectionPoint(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& vertex);

}  // namespace specula::math
