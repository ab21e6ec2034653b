#pragma once
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "math/Camera.h"
#include "math/Transform.h"

namespace specula::scene {

// Rotation about an axis through the object's own translation (its pivot).
struct Spin {
  glm::vec3 axis{0.0f, 1.0f, 0.0f};  // unit
  double degreesPerSecond = 0.0;
};

// Rotation of the object's position (the camera's eye) about an axis through `center`.
// An orbiting object also turns to keep facing the same way relative to the centre.
struct Orbit {
  glm::vec3 center{0.0f};
  glm::vec3 axis{0.0f, 1.0f, 0.0f};  // unit
  double degreesPerSecond = 0.0;
};

// Keyframed object transforms: translation and scale linear, rotation slerped.
struct TransformKey {
  double time = 0.0;  // seconds, strictly increasing along the path
  math::Transform transform;
};
struct TransformPath {
  std::vector<TransformKey> keys;  // at least one
  bool loop = true;                // false: hold the last key after the end
};

// Keyframed camera: eye, target and up linear, fov linear.
struct CameraKey {
  double time = 0.0;
  math::Camera camera;
};
struct CameraPath {
  std::vector<CameraKey> keys;
  bool loop = true;
};

struct Animation {
  std::optional<std::uint32_t> object;  // index into Scene::objects; nullopt animates the camera
  std::variant<Spin, Orbit, TransformPath, CameraPath> motion;  // CameraPath only for the camera,
                                                                // TransformPath and Spin only for objects
};

}  // namespace specula::scene
