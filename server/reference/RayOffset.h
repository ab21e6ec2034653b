#pragma once
#include <glm/glm.hpp>

namespace specula::reference {

// The origin for a ray leaving surface point `p` on the side `n` points to (Wächter & Binder, "A Fast
// and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6): moves each coordinate a
// fixed number of float ulps along n, so the step scales with |p| where a fixed epsilon would be too
// small far from the origin and too large near it; coordinates near 0 get a small absolute step.
// n need not be unit but should be roughly so (its components scale the step).
glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n);

}  // namespace specula::reference
