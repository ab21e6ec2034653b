#pragma once
#include <glm/glm.hpp>
#include <limits>

namespace specula::math {

// Axis-aligned box; empty until a point is added.
struct Bounds {
  glm::vec3 low{std::numeric_limits<float>::max()};
  glm::vec3 high{std::numeric_limits<float>::lowest()};

  bool empty() const { return low.x > high.x; }
  void add(const glm::vec3& point) {
    low = glm::min(low, point);
    high = glm::max(high, point);
  }
  void add(const Bounds& other) {
    if (!other.empty()) {
      add(other.low);
      add(other.high);
    }
  }
  glm::vec3 center() const { return 0.5f * (low + high); }
  float radius() const { return 0.5f * glm::length(high - low); }  // of the enclosing sphere

  // The box enclosing this box after an affine transform.
  Bounds transformed(const glm::mat4& transform) const {
    Bounds result;
    if (empty()) return result;
    for (int corner = 0; corner < 8; ++corner)
      result.add(glm::vec3(transform * glm::vec4((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y,
                                                 (corner & 4) ? high.z : low.z, 1.0f)));
    return result;
  }
};

}  // namespace specula::math
