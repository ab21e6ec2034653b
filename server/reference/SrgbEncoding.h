#pragma once
#include <cstdint>
#include <glm/glm.hpp>

namespace specula::reference {

// The byte a GL sRGB8 framebuffer stores for a linear colour channel:
// round(255 · linearToSrgb(clamp(c, 0, 1))).
std::uint8_t srgb8(float linear);

// The RGBA bytes of an opaque linear colour (alpha 255).
void writeSrgb8(const glm::vec3& linear, std::uint8_t* rgba);

}  // namespace specula::reference
