#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace specula::scene {

// Two-colour checkerboard over the uv square: cell (floor(u*cellsPerUnit) + floor(v*cellsPerUnit)) even
// takes the material's baseColor, odd takes oddColor.
struct Checker {
  glm::vec3 oddColor{0.0f};  // linear RGB
  float cellsPerUnit = 1.0f;
};

struct Material {
  std::string name;
  glm::vec3 baseColor{0.8f};  // linear RGB (scene files hold sRGB; loaders convert)
  bool unlit = false;         // emissive: the colour written is the colour stored, no lighting
  std::optional<Checker> checker;
  // Index into Scene::textures: its colour (sRGB texels, decoded to linear) multiplies the base or
  // checker colour at the surface's uv; v = 0 is the image's first (top) row, as in glTF.
  std::optional<std::uint32_t> texture;
  float reflectivity = 0.0f;  // share of the mirror image blended over the surface, in [0, 1]
};

}  // namespace specula::scene
