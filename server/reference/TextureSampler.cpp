#include "reference/TextureSampler.h"

#include <algorithm>
#include <cmath>

#include "math/Color.h"

namespace specula::reference {

namespace {

constexpr float kMinFootprintCosine = 0.01f;  // shading.glsl's

// A texel index outside [0, size) brought inside as GL's wrap mode does.
int wrapIndex(int i, int size, scene::TextureWrap wrap) {
  switch (wrap) {
    case scene::TextureWrap::ClampToEdge: return std::clamp(i, 0, size - 1);
    case scene::TextureWrap::MirroredRepeat: {
      const int period = 2 * size, m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case scene::TextureWrap::Repeat: break;
  }
  return ((i % size) + size) % size;
}

glm::vec4 texel(const scene::TextureLevel& level, int x, int y) {
  const std::uint8_t* t =
      &level.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) + static_cast<std::size_t>(x)) *
                  4];
  return {math::srgbByteToLinear(t[0]), math::srgbByteToLinear(t[1]), math::srgbByteToLinear(t[2]),
          static_cast<float>(t[3]) / 255.0f};
}

glm::vec4 bilinear(const scene::Texture& texture, const scene::TextureLevel& level, glm::vec2 uv) {
  // Wrap the coordinate's integer part first so huge uv keep their fraction's precision.
  const double u = static_cast<double>(uv.x) * level.width - 0.5, v = static_cast<double>(uv.y) * level.height - 0.5;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const auto fu = static_cast<float>(u - u0), fv = static_cast<float>(v - v0);
  const auto wrapped = [&](double i, int size, scene::TextureWrap wrap) {
    return wrapIndex(static_cast<int>(std::fmod(i, 4.0 * size)), size, wrap);  // a multiple of both periods
  };
  const int x0 = wrapped(u0, level.width, texture.wrapU), x1 = wrapped(u0 + 1.0, level.width, texture.wrapU);
  const int y0 = wrapped(v0, level.height, texture.wrapV), y1 = wrapped(v0 + 1.0, level.height, texture.wrapV);
  return glm::mix(glm::mix(texel(level, x0, y0), texel(level, x1, y0), fu),
                  glm::mix(texel(level, x0, y1), texel(level, x1, y1), fu), fv);
}

}  // namespace

glm::vec4 sampleTexture(const scene::Texture& texture, glm::vec2 uv, float uvFootprint) {
  const scene::TextureLevel& base = texture.levels.front();
  const float rho = uvFootprint * static_cast<float>(std::max(base.width, base.height));
  if (!(rho > 1.0f) || texture.levels.size() == 1)
    return bilinear(texture, base, uv);  // magnified (or NaN): the base level
  const float lod = std::min(std::log2(rho), static_cast<float>(texture.levels.size() - 1));
  const auto fine = static_cast<std::size_t>(lod);
  const std::size_t coarse = std::min(fine + 1, texture.levels.size() - 1);
  return glm::mix(bilinear(texture, texture.levels[fine], uv), bilinear(texture, texture.levels[coarse], uv),
                  lod - static_cast<float>(fine));
}

float pixelFootprint(float pathLength, float eyeDepthPerLength, float pixelAngle, float cosine) {
  return pathLength * eyeDepthPerLength * pixelAngle / std::max(std::abs(cosine), kMinFootprintCosine);
}

}  // namespace specula::reference
