#pragma once
// The slab test of a ray against an axis-aligned box, for the CPU's hierarchies (float and double).
#include <algorithm>
#include <glm/glm.hpp>

namespace specula::math {

// Whether origin + t·direction meets the box [low, high] for some t in [tMin, tMax]; `inverse` is
// 1 / direction, per axis (infinite where the direction has no component).
template <typename T>
bool rayMeetsBox(const glm::vec<3, T>& low, const glm::vec<3, T>& high, const glm::vec<3, T>& origin,
                 const glm::vec<3, T>& inverse, T tMin, T tMax) {
  const glm::vec<3, T> t0 = (low - origin) * inverse, t1 = (high - origin) * inverse;
  const glm::vec<3, T> near = glm::min(t0, t1), far = glm::max(t0, t1);
  return std::max({near.x, near.y, near.z, tMin}) <= std::min({far.x, far.y, far.z, tMax});
}

}  // namespace specula::math
