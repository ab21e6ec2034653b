#include "reference/SurfaceShader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "reference/TextureSampler.h"

namespace specula::reference {

namespace {

glm::vec3 checkerColor(const scene::Material& material, const glm::vec2& uv) {
  if (!material.checker) return material.baseColor;
  const glm::vec2 scaled = uv * material.checker->cellsPerUnit;
  const auto cellX = static_cast<std::int64_t>(std::floor(scaled.x));
  const auto cellY = static_cast<std::int64_t>(std::floor(scaled.y));
  return ((cellX + cellY) & 1) == 0 ? material.baseColor : material.checker->oddColor;
}

}  // namespace

SurfaceShader::SurfaceShader(const scene::Scene& scene) : textures_(scene.textures), ambient_(scene.ambient) {
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const scene::Light& light = scene.lights[i];
    const float w = light.kind == scene::Light::Kind::Point ? 1.0f : 0.0f;
    lights_.push_back({glm::vec4(light.vector, w), light.color * light.intensity});
  }
}

glm::vec3 SurfaceShader::shade(const scene::Material& material, const glm::vec3& position, const glm::vec3& normal,
                               const glm::vec2& uv, float uvFootprint, const glm::vec3& viewer) const {
  glm::vec3 albedo = checkerColor(material, uv);
  if (material.texture) albedo *= glm::vec3(sampleTexture(textures_[*material.texture], uv, uvFootprint));
  if (material.unlit) return albedo;
  glm::vec3 n = glm::normalize(normal);
  if (glm::dot(n, viewer - position) < 0.0f) n = -n;
  glm::vec3 color = ambient_ * albedo;
  for (const ShaderLight& light : lights_) {
    const glm::vec3 toLight =
        light.vector.w == 0.0f ? glm::vec3(light.vector) : glm::normalize(glm::vec3(light.vector) - position);
    color += albedo * light.color * std::max(glm::dot(n, toLight), 0.0f);
  }
  return color;
}

}  // namespace specula::reference
