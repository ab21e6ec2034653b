#include "math/SphereReflection.h"

#include <algorithm>
#include <cmath>

namespace specula::math {

namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// Sum of the tangential components of the unit directions to eye and vertex at angle θ on the unit
// circle: positive while R is nearer the eye's side, negative past the reflection point.
double tangentialBalance(double theta, const glm::dvec2& eye, const glm::dvec2& vertex) {
  const glm::dvec2 n(std::cos(theta), std::sin(theta));
  return cross2(n, glm::normalize(eye - n)) + cross2(n, glm::normalize(vertex - n));
}

}  // namespace

std::optional<glm::dvec3> sphereReflectionPoint(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& vertex) {
  // Work on the unit sphere at the origin.
  const glm::dvec3 e = (eye - sphere.center) / sphere.radius;
  const glm::dvec3 v = (vertex - sphere.center) / sphere.radius;
  const double eyeDistance = glm::length(e), vertexDistance = glm::length(v);
  if (!(eyeDistance > 1.0) || !(vertexDistance > 1.0) || !std::isfinite(eyeDistance) || !std::isfinite(vertexDistance))
    return std::nullopt;

  // Plane basis: x towards the eye, y towards the vertex's component perpendicular to it.
  const glm::dvec3 x = e / eyeDistance;
  const glm::dvec3 perpendicular = v - glm::dot(v, x) * x;
  const double perpendicularLength = glm::length(perpendicular);
  const double along = glm::dot(v, x);
  if (perpendicularLength <= 1e-14 * vertexDistance) {
    // Collinear: in front of the sphere the reflection point faces the eye; behind it, it is hidden.
    if (along > 0.0) return sphere.center + sphere.radius * x;
    return std::nullopt;
  }
  const glm::dvec3 y = perpendicular / perpendicularLength;
  const double gamma = std::atan2(perpendicularLength, along);  // angle eye–centre–vertex, in (0, π]

  // R must be seen from both: within acos(1/d) of the eye's and of the vertex's direction.
  const double low = std::max(0.0, gamma - std::acos(1.0 / vertexDistance));
  const double high = std::min(gamma, std::acos(1.0 / eyeDistance));
  if (low > high) return std::nullopt;

  const glm::dvec2 eye2(eyeDistance, 0.0), vertex2(vertexDistance * std::cos(gamma), vertexDistance * std::sin(gamma));
  double a = low, b = high;
  double fa = tangentialBalance(a, eye2, vertex2);
  const double fb = tangentialBalance(b, eye2, vertex2);
  double theta;
  if (fa <= 0.0 || fb >= 0.0) {
    // Rounding at a bracket end that is itself the solution (grazing or touching cases).
    theta = std::abs(fa) <= std::abs(fb) ? a : b;
  } else {
    for (int iteration = 0; iteration < 200 && b - a > 1e-16 * std::max(1.0, b); ++iteration) {
      const double mid = 0.5 * (a + b);
      const double fm = tangentialBalance(mid, eye2, vertex2);
      if ((fm > 0.0) == (fa > 0.0)) {
        a = mid;
        fa = fm;
      } else {
        b = mid;
      }
    }
    theta = 0.5 * (a + b);
  }
  return sphere.center + sphere.radius * (std::cos(theta) * x + std::sin(theta) * y);
}

}  // namespace specula::math
