#include "math/Transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace specula::math {

glm::mat4 Transform::matrix() const {
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

glm::mat3 normalMatrix(const glm::mat4& objectToWorld) {
  return glm::transpose(glm::inverse(glm::mat3(objectToWorld)));
}

}  // namespace specula::math
