#include "math/Reflection.h"

namespace specula::math {

double reflectionError(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& eye, const glm::dvec3& vertex) {
  const glm::dvec3 bisector = glm::normalize(eye - r) + glm::normalize(vertex - r);
  return 1.0 - glm::dot(glm::normalize(bisector), n);
}

glm::dvec3 virtualVertex(const glm::dvec3& eye, const glm::dvec3& r, const glm::dvec3& vertex) {
  const glm::dvec3 ray = r - eye;
  const double toMirror = glm::length(ray);
  return eye + (toMirror + glm::length(vertex - r)) / toMirror * ray;
}

glm::dvec3 mirrorAcrossPlane(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& vertex) {
  return vertex - 2.0 * glm::dot(vertex - r, n) * n;
}

}  // namespace specula::math
