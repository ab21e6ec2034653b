#include "reference/AnalyticSurface.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace specula::reference {

namespace {

// Both roots of |o + t·d|² = 1, lower first, or nullopt when the line misses the unit sphere.
std::optional<std::pair<double, double>> unitSphereRoots(const glm::dvec3& o, const glm::dvec3& d) {
  const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
  // Discriminant from the closest-approach vector (Haines et al., Ray Tracing Gems ch. 7): no
  // cancellation between b² and a·c when the origin is far away.
  const glm::dvec3 f = o - (b / a) * d;
  const double discriminant = a * (1.0 - glm::dot(f, f));
  if (discriminant < 0.0) return std::nullopt;
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0) return std::pair{0.0, 0.0};  // grazing at the origin itself
  const double t0 = q / a, t1 = c / q;
  return std::pair{std::min(t0, t1), std::max(t0, t1)};
}

}  // namespace

AnalyticSurface::AnalyticSurface(const scene::AnalyticShape& shape, const glm::mat4& objectToWorld)
    : unitToWorld_(glm::dmat4(objectToWorld) * glm::translate(glm::dmat4(1.0), glm::dvec3(shape.center)) *
                   glm::scale(glm::dmat4(1.0), glm::dvec3(shape.radii))),
      worldToUnit_(glm::inverse(unitToWorld_)),
      normalToWorld_(glm::transpose(glm::dmat3(worldToUnit_))) {}

glm::dvec3 AnalyticSurface::toUnit(const glm::dvec3& point) const {
  return glm::dvec3(worldToUnit_ * glm::dvec4(point, 1.0));
}

std::optional<double> AnalyticSurface::intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                                 double tMax) const {
  const auto roots = unitSphereRoots(toUnit(origin), glm::dmat3(worldToUnit_) * direction);
  if (!roots) return std::nullopt;
  for (const double t : {roots->first, roots->second})
    if (t > tMin && t < tMax) return t;
  return std::nullopt;
}

std::optional<double> AnalyticSurface::intersectLeaving(const SurfaceExit& exit, const glm::dvec3& origin,
                                                        const glm::dvec3& direction, double tMin, double tMax) const {
  if (exit.outside) return std::nullopt;
  // With the start on the surface one root is exactly 0; the other is −2(o·d)/(d·d).
  const glm::dvec3 o = toUnit(exit.point), d = glm::dmat3(worldToUnit_) * direction;
  const double fromExit = -2.0 * glm::dot(o, d) / glm::dot(d, d);
  const double t = fromExit + glm::dot(exit.point - origin, direction) / glm::dot(direction, direction);
  if (fromExit > 0.0 && t > tMin && t < tMax) return t;
  return std::nullopt;
}

glm::dvec3 AnalyticSurface::surfacePoint(const glm::dvec3& origin, const glm::dvec3& direction, double t) const {
  const glm::dvec3 unit = glm::normalize(toUnit(origin) + t * (glm::dmat3(worldToUnit_) * direction));
  return glm::dvec3(unitToWorld_ * glm::dvec4(unit, 1.0));
}

glm::dvec3 AnalyticSurface::outwardNormal(const glm::dvec3& point) const {
  return glm::normalize(normalToWorld_ * toUnit(point));
}

glm::vec2 AnalyticSurface::uv(const glm::dvec3& point) const {
  const glm::dvec3 p = glm::normalize(toUnit(point));
  double longitude = std::atan2(-p.z, p.x);  // uvSphere turns +x towards −z
  if (longitude < 0.0) longitude += glm::two_pi<double>();
  const double latitude = std::acos(std::clamp(-p.y, -1.0, 1.0));
  return {static_cast<float>(longitude / glm::two_pi<double>()), static_cast<float>(latitude / glm::pi<double>())};
}

std::pair<glm::dvec3, glm::dvec3> AnalyticSurface::bounds() const {
  // The unit sphere's image reaches |row i of the linear part| either side of the centre along axis i.
  const glm::dmat3 linear(unitToWorld_);
  const glm::dvec3 halfExtent(glm::length(glm::row(linear, 0)), glm::length(glm::row(linear, 1)),
                              glm::length(glm::row(linear, 2)));
  const glm::dvec3 centre(unitToWorld_[3]);
  return {centre - halfExtent, centre + halfExtent};
}

}  // namespace specula::reference
