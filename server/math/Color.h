#pragma once
// sRGB transfer functions (IEC 61966-2-1). Scene files hold sRGB; shading happens in linear RGB.
#include <cstdint>
#include <glm/glm.hpp>

namespace specula::math {

float srgbToLinear(float srgb);
float linearToSrgb(float linear);
glm::vec3 srgbToLinear(const glm::vec3& srgb);
// An sRGB-encoded byte (what an sRGB8 texel or framebuffer holds) as a linear value in [0, 1] (a table).
float srgbByteToLinear(std::uint8_t srgb);

}  // namespace specula::math
