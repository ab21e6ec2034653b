#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "math/Transform.h"
#include "scene/MirrorInfo.h"

namespace specula::scene {

struct SceneObject {
  std::string name;            // unique within a scene
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t material = 0;  // index into Scene::materials
  math::Transform transform;   // rest pose; animations replace it over time
  std::optional<MirrorInfo> mirror;
  bool reflected = true;  // appears in mirrors; false skips its reflection-point search entirely
};

}  // namespace specula::scene
