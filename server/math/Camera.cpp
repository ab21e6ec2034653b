#include "math/Camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace specula::math {

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

std::optional<std::string> cameraProblem(const Camera& camera) {
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up) || !std::isfinite(camera.fovYDegrees))
    return "camera has a non-finite value";
  if (!(camera.fovYDegrees > 0.0f && camera.fovYDegrees < 180.0f)) return "camera fov must lie in (0, 180) degrees";
  const glm::vec3 forward = camera.target - camera.eye;
  const float forwardLength = glm::length(forward);
  if (!(forwardLength > 1e-6f * std::max(1.0f, glm::length(camera.eye)))) return "camera eye and target coincide";
  if (!(glm::length(camera.up) > 0.0f)) return "camera up vector is zero";
  const float sine = glm::length(glm::cross(forward / forwardLength, glm::normalize(camera.up)));
  if (!(sine > 1e-4f)) return "camera up vector is parallel to the view direction";
  return std::nullopt;
}

glm::mat4 viewMatrix(const Camera& camera) { return glm::lookAt(camera.eye, camera.target, camera.up); }

glm::mat4 projectionMatrix(const Camera& camera, float aspect, float nearDistance, float farDistance) {
  return glm::perspective(glm::radians(camera.fovYDegrees), aspect, nearDistance, farDistance);
}

}  // namespace specula::math
