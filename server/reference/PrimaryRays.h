#pragma once
#include <glm/glm.hpp>

#include "math/Camera.h"

namespace specula::reference {

// One ray through each pixel centre with the rasterizer's camera: the glm::lookAt basis, a
// glm::perspective vertical field of view, aspect width / height, row 0 at the top of the image.
class PrimaryRays {
 public:
  // Requires math::cameraProblem(camera) == nullopt and positive sizes.
  PrimaryRays(const math::Camera& camera, int width, int height);

  const glm::vec3& origin() const { return origin_; }
  // Unit world direction through the centre of pixel (column, row), or `offset` pixels from it
  // (x to the right, y down: math::samplePattern's sample points).
  glm::dvec3 direction(int column, int row, glm::vec2 offset = glm::vec2(0.0f)) const;
  // The view axis, world, unit.
  glm::dvec3 forward() const { return forward_; }

 private:
  glm::vec3 origin_;
  glm::dvec3 forward_, right_, up_;
  glm::dvec2 halfExtent_;  // tan(fov / 2) · (aspect, 1): the image plane at distance 1
  glm::dvec2 size_;
};

}  // namespace specula::reference
