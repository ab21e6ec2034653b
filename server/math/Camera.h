#pragma once
// A pinhole camera: world space (right-handed, y up, metres), vertical field of view in degrees.
#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace specula::math {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = 45.0f;

  bool operator==(const Camera&) const = default;
};

// Why a camera cannot produce a view (eye on target, up parallel to the view direction,
// fov outside (0, 180), non-finite values), or nullopt when it can.
std::optional<std::string> cameraProblem(const Camera& camera);

// World → eye space, OpenGL convention (looking down −z). Requires cameraProblem() == nullopt.
glm::mat4 viewMatrix(const Camera& camera);

// Eye → clip space for a viewport aspect (width / height) and positive near < far distances.
glm::mat4 projectionMatrix(const Camera& camera, float aspect, float nearDistance, float farDistance);

}  // namespace specula::math
