#pragma once
// Translation, rotation, scale: object space → parent (world) space, applied scale first.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace specula::math {

struct Transform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};

  glm::mat4 matrix() const;
};

// Matrix that carries object-space normals to world space for an object-to-world matrix.
glm::mat3 normalMatrix(const glm::mat4& objectToWorld);

}  // namespace specula::math
