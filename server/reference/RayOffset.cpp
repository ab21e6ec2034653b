#include "reference/RayOffset.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace specula::reference {

namespace {

// Constants from the paper: 256 ulps away from zero, 1/65536 absolute inside |x| < 1/32.
constexpr float kOrigin = 1.0f / 32.0f;
constexpr float kFloatScale = 1.0f / 65536.0f;
constexpr float kIntScale = 256.0f;

float offsetCoordinate(float p, float n) {
  if (std::abs(p) < kOrigin) return p + kFloatScale * n;
  const auto ulps = static_cast<std::int32_t>(kIntScale * n);
  // Adding to the bit pattern moves away from zero for positive p, so the sign of p flips the step.
  return std::bit_cast<float>(std::bit_cast<std::int32_t>(p) + (p < 0.0f ? -ulps : ulps));
}

}  // namespace

glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
  return {offsetCoordinate(p.x, n.x), offsetCoordinate(p.y, n.y), offsetCoordinate(p.z, n.z)};
}

}  // namespace specula::reference
