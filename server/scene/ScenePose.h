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
  // One per Scene::objects entry: the weights of its mesh's morph targets, empty where it has none.
  std::vector<std::vector<float>> morphWeights;
  // One per Scene::objects entry: the matrices taking its skinned mesh to object space, one per joint
  // of its skin (linear blend skinning), empty where it has no skin.
  std::vector<std::vector<glm::mat4>> jointMatrices;
  math::Camera camera;

  bool operator==(const ScenePose&) const = default;

  static ScenePose at(const Scene& scene, double seconds);
};

}  // namespace specula::scene
