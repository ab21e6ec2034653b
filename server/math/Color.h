#pragma once
// sRGB transfer functions (IEC 61966-2-1). Scene files hold sRGB; shading happens in linear RGB.
#include <glm/glm.hpp>

namespace specula::math {

float srgbToLinear(float srgb);
float linearToSrgb(float linear);
glm::vec3 srgbToLinear(const glm::vec3& srgb);

}  // namespace specula::math
