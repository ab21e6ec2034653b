#pragma once
#include <glm/glm.hpp>

namespace specula::scene {

struct Light {
  enum class Kind { Directional, Point };
  Kind kind = Kind::Directional;
  glm::vec3 vector{0.0f, 1.0f, 0.0f};  // directional: unit direction towards the light; point: world position
  glm::vec3 color{1.0f};               // linear RGB
  float intensity = 1.0f;
};

}  // namespace specula::scene
