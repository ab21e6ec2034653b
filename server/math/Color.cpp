#include "math/Color.h"

#include <array>
#include <cmath>

namespace specula::math {

float srgbToLinear(float srgb) { return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f); }

float linearToSrgb(float linear) {
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 srgbToLinear(const glm::vec3& srgb) {
  return {srgbToLinear(srgb.x), srgbToLinear(srgb.y), srgbToLinear(srgb.z)};
}

float srgbByteToLinear(std::uint8_t srgb) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = srgbToLinear(static_cast<float>(i) / 255.0f);
    return values;
  }();
  return table[srgb];
}

}  // namespace specula::math
