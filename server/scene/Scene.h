#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "math/Camera.h"
#include "scene/Animation.h"
#include "scene/Environment.h"
#include "scene/Light.h"
#include "scene/Material.h"
#include "scene/Mesh.h"
#include "scene/NodeRig.h"
#include "scene/SceneObject.h"
#include "scene/Texture.h"

namespace specula::scene {

// Lights a scene may have: every renderer shades with all of them (shaders/common/shading.glsl
// declares arrays of this size; a GL test checks the two agree).
inline constexpr std::size_t kMaxLights = 8;

// Everything needed to render any frame of a scene: assets, rest pose, animations.
// Immutable after loading; sessions share it read-only and keep their own clock and overrides.
struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what materials' `texture` indices name
  std::vector<SceneObject> objects;
  std::vector<Light> lights;
  glm::vec3 ambient{0.05f};    // linear RGB added to every lit surface
  glm::vec3 background{0.0f};  // linear RGB: the environment when it is a colour
  Environment environment;     // what rays that meet nothing see
  math::Camera camera;         // default camera (rest pose of the camera animation, if any)
  std::vector<Animation> animations;
  NodeRig rig;  // glTF nodes: their animations, and the objects and camera they carry
  // What loading read differently from the files or left out, one line each, for the user: printed when
  // the scene loads and sent in every session's welcome.
  std::vector<std::string> notes;

  std::size_t vertexCount() const;
  std::size_t triangleCount() const;
  std::size_t mirrorCount() const;
  bool moves() const { return !animations.empty() || rig.moves(); }  // anything changes with time
};

}  // namespace specula::scene
