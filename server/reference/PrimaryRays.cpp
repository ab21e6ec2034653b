#include "reference/PrimaryRays.h"

#include <cassert>
#include <cmath>

namespace specula::reference {

PrimaryRays::PrimaryRays(const math::Camera& camera, int width, int height)
    : origin_(camera.eye), size_(width, height) {
  assert(!math::cameraProblem(camera) && width > 0 && height > 0);
  // The basis glm::lookAt builds, in double.
  forward_ = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
  right_ = glm::normalize(glm::cross(forward_, glm::dvec3(camera.up)));
  up_ = glm::cross(right_, forward_);
  const double tanHalf = std::tan(glm::radians(static_cast<double>(camera.fovYDegrees)) / 2.0);
  halfExtent_ = {tanHalf * size_.x / size_.y, tanHalf};
}

glm::dvec3 PrimaryRays::direction(int column, int row, glm::vec2 offset) const {
  const double x = 2.0 * (column + 0.5 + offset.x) / size_.x - 1.0;
  const double y = 1.0 - 2.0 * (row + 0.5 + offset.y) / size_.y;
  return glm::normalize(forward_ + x * halfExtent_.x * right_ + y * halfExtent_.y * up_);
}

}  // namespace specula::reference
