#include "math/ExtrusionReflection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace specula::math {

namespace {

glm::dvec2 rotated90(const glm::dvec2& n) { return {-n.y, n.x}; }

}  // namespace

Extrusion Extrusion::along(const glm::dvec3& axisPoint, const glm::dvec3& direction, const glm::dvec2& radii) {
  Extrusion extrusion;
  extrusion.axisPoint = axisPoint;
  extrusion.direction = glm::normalize(direction);
  const glm::dvec3 reference =
      std::abs(extrusion.direction.x) > 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  extrusion.u = glm::normalize(reference - glm::dot(reference, extrusion.direction) * extrusion.direction);
  extrusion.v = glm::cross(extrusion.u, extrusion.direction);
  extrusion.radii = radii;
  return extrusion;
}

std::optional<Extrusion> Extrusion::transformed(const glm::dmat4& objectToWorld) const {
  const glm::dmat3 linear(objectToWorld);
  const glm::dvec3 generator = linear * direction;
  const double generatorLength = glm::length(generator);
  if (!(generatorLength > 0.0) || !std::isfinite(generatorLength)) return std::nullopt;
  Extrusion world;
  world.direction = generator / generatorLength;
  world.axisPoint = glm::dvec3(objectToWorld * glm::dvec4(axisPoint, 1.0));
  // The cross-section ⊥ the generator is the profile's image slid along it: t ↦ K (cos t, sin t)
  // with K's columns the mapped semi-axes less their generator components. Its semi-axes are K's
  // singular values, along K's left singular vectors (from the eigenvectors of KᵀK).
  const auto acrossGenerator = [&](const glm::dvec3& w) { return w - glm::dot(w, world.direction) * world.direction; };
  const glm::dvec3 k1 = acrossGenerator(linear * u * radii.x), k2 = acrossGenerator(linear * v * radii.y);
  const double theta = 0.5 * std::atan2(2.0 * glm::dot(k1, k2), glm::dot(k1, k1) - glm::dot(k2, k2));
  const glm::dvec3 major = std::cos(theta) * k1 + std::sin(theta) * k2;
  const glm::dvec3 minor = -std::sin(theta) * k1 + std::cos(theta) * k2;
  world.radii = {glm::length(major), glm::length(minor)};
  const double scale = std::max(world.radii.x, world.radii.y);
  if (!(std::min(world.radii.x, world.radii.y) > 1e-12 * scale) || !std::isfinite(scale)) return std::nullopt;
  world.u = major / world.radii.x;
  world.v = glm::normalize(minor - glm::dot(minor, world.u) * world.u);
  return world;
}

glm::dvec3 Extrusion::pointAt(double t, double height) const {
  return axisPoint + radii.x * std::cos(t) * u + radii.y * std::sin(t) * v + height * direction;
}

glm::dvec3 Extrusion::normalAt(double t) const {
  return glm::normalize(radii.y * std::cos(t) * u + radii.x * std::sin(t) * v);
}

std::optional<SurfacePoint> extrusionReflectionPoint(const Extrusion& extrusion, const glm::dvec3& eye,
                                                     const glm::dvec3& vertex) {
  // (1) Project onto the profile's plane: 2-D points in (u, v), heights along the direction.
  const glm::dvec3 eyeOffset = eye - extrusion.axisPoint, vertexOffset = vertex - extrusion.axisPoint;
  const glm::dvec2 eye2(glm::dot(eyeOffset, extrusion.u), glm::dot(eyeOffset, extrusion.v));
  const glm::dvec2 vertex2(glm::dot(vertexOffset, extrusion.u), glm::dot(vertexOffset, extrusion.v));
  const glm::dvec2 radii = extrusion.radii;
  // In the coordinates that make the profile a unit circle (tangency survives the affine map), the
  // arc a point outside sees is centred on its direction, acos(1 / distance) to either side.
  const glm::dvec2 eyeUnit = eye2 / radii, vertexUnit = vertex2 / radii;
  const double eyeDistance = glm::length(eyeUnit), vertexDistance = glm::length(vertexUnit);
  if (!(eyeDistance > 1.0) || !(vertexDistance >= 1.0) || !std::isfinite(eyeDistance) || !std::isfinite(vertexDistance))
    return std::nullopt;
  const double eyeAngle = std::atan2(eyeUnit.y, eyeUnit.x);
  const double eyeHalfArc = std::acos(1.0 / eyeDistance), vertexHalfArc = std::acos(1.0 / vertexDistance);
  const double offset = std::remainder(std::atan2(vertexUnit.y, vertexUnit.x) - eyeAngle, 2.0 * std::numbers::pi);
  // (2) The arc both see, relative to the eye's direction; empty: the vertex is in the eye's shadow.
  // Both arcs are shorter than π, so they overlap in one interval at most.
  double low = std::max(-eyeHalfArc, offset - vertexHalfArc), high = std::min(eyeHalfArc, offset + vertexHalfArc);
  if (low > high) return std::nullopt;

  // The tangential balance of the unit directions to eye and vertex: at the arc's clockwise end one
  // of them runs along the curve's counter-clockwise tangent (+1), at the other end against it (−1),
  // and the reflected rays of a convex curve never cross outside it, so the balance falls through
  // zero once, at the reflection point: bisection is the binary search over the subdivision's cells.
  const auto balance = [&](double s) {
    const double t = eyeAngle + s;
    const glm::dvec2 point(radii.x * std::cos(t), radii.y * std::sin(t));
    const glm::dvec2 tangent = rotated90(glm::normalize(glm::dvec2(radii.y * std::cos(t), radii.x * std::sin(t))));
    return glm::dot(tangent, glm::normalize(eye2 - point)) + glm::dot(tangent, glm::normalize(vertex2 - point));
  };
  double fLow = balance(low);
  const double fHigh = balance(high);
  double s;
  if (!(fLow > 0.0) || !(fHigh < 0.0)) {
    s = std::abs(fLow) <= std::abs(fHigh) ? low : high;  // rounding at an end that is itself the answer
  } else {
    for (int iteration = 0; iteration < 200 && high - low > 1e-16 * std::max(1.0, std::abs(high)); ++iteration) {
      const double mid = 0.5 * (low + high);
      const double fMid = balance(mid);
      if (fMid > 0.0) {
        low = mid;
        fLow = fMid;
      } else {
        high = mid;
      }
    }
    s = 0.5 * (low + high);
  }
  const double t = eyeAngle + s;

  // (3)–(4) The plane of reflection is the tangent line extruded; the path eye → R → vertex crosses
  // it where the heights divide as the 2-D distances do (the mirrored vertex lies on the eye's ray).
  const glm::dvec2 point(radii.x * std::cos(t), radii.y * std::sin(t));
  const double toEye = glm::distance(eye2, point), toVertex = glm::distance(vertex2, point);
  const double eyeHeight = glm::dot(eyeOffset, extrusion.direction);
  const double vertexHeight = glm::dot(vertexOffset, extrusion.direction);
  const double share = toEye + toVertex > 0.0 ? toEye / (toEye + toVertex) : 0.0;
  return SurfacePoint{extrusion.pointAt(t, eyeHeight + (vertexHeight - eyeHeight) * share), extrusion.normalAt(t), t};
}

}  // namespace specula::math
