#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "math/Camera.h"
#include "scene/Scene.h"

namespace specula::scene {

// The scene at one instant: where every object and the camera are. A pure function of (scene, time),
// so any frame can be rendered deterministically and sessions can seek freely.
struct ScenePose {
  double seconds = 0.0;
  std::vector<glm::mat4> objectToWorld;  // one per Scene::objects entry
  math::Camera camera;

  bool operator==(const ScenePose&) const = default;

  static ScenePose at(const Scene& scene, double seconds);
};

}  // namespace specula::scene
