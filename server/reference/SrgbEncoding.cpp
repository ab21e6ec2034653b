#include "reference/SrgbEncoding.h"

#include <algorithm>
#include <cmath>

#include "math/Color.h"

namespace specula::reference {

std::uint8_t srgb8(float linear) {
  return static_cast<std::uint8_t>(std::lround(255.0f * math::linearToSrgb(std::clamp(linear, 0.0f, 1.0f))));
}

void writeSrgb8(const glm::vec3& linear, std::uint8_t* rgba) {
  rgba[0] = srgb8(linear.x);
  rgba[1] = srgb8(linear.y);
  rgba[2] = srgb8(linear.z);
  rgba[3] = 255;
}

}  // namespace specula::reference
