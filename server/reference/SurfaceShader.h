#pragma once
// shaders/common/shading.glsl restated in C++, float for float, so reference pixels are lit exactly
// as rasterized ones: same albedo, same two-sided Lambert, same light limit, no shadows.
#include <glm/glm.hpp>
#include <vector>

#include "scene/Scene.h"

namespace specula::reference {

class SurfaceShader {
 public:
  explicit SurfaceShader(const scene::Scene& scene);

  // Linear RGB of a surface point seen from `viewer` (world space): shadeSurfaceOver() of shading.glsl,
  // the material's texture filtered over `uvFootprint` uv units. `normal` need not be unit (it is
  // normalised, as the fragment shader does).
  glm::vec3 shade(const scene::Material& material, const glm::vec3& position, const glm::vec3& normal,
                  const glm::vec2& uv, float uvFootprint, const glm::vec3& viewer) const;

 private:
  struct ShaderLight {
    glm::vec4 vector;  // w = 0: unit direction towards the light; w = 1: position
    glm::vec3 color;   // colour × intensity
  };

  const std::vector<scene::Texture>& textures_;
  glm::vec3 ambient_;
  std::vector<ShaderLight> lights_;
};

}  // namespace specula::reference
