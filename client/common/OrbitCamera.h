#pragma once
// A camera orbiting a target (yaw, pitch, radius), as the native clients move it; the browser client
// has the same model in JavaScript.
#include <glm/glm.hpp>

#include "specula.pb.h"

namespace specula::client {

struct OrbitCamera {
  glm::vec3 target{0.0f}, up{0.0f, 1.0f, 0.0f};
  float yaw = 0.0f, pitch = 0.0f;  // radians; yaw 0 looks from +z
  float radius = 5.0f;
  float fovDegrees = 45.0f;

  // The orbit that puts the eye where `camera` has it.
  static OrbitCamera from(const v1::CameraUpdate& camera);
  glm::vec3 eye() const;

  void orbit(float yawRadians, float pitchRadians);  // pitch stays within ±89°
  void zoom(float factor);                           // radius × factor
  void pan(float right, float upward);               // in world units along the view's axes

  // A camera update message for the current pose.
  v1::ClientMessage message(std::uint64_t sequence, double clientTimeMs) const;
};

}  // namespace specula::client
