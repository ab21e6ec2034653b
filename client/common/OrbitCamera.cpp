#include "OrbitCamera.h"

#include "CameraConversions.h"

#include <algorithm>
#include <cmath>

namespace specula::client {

namespace {
using protocol::toGlm;
constexpr float kMaxPitch = 1.55f;
}  // namespace

OrbitCamera OrbitCamera::from(const v1::CameraUpdate& camera) {
  OrbitCamera orbit;
  orbit.target = toGlm(camera.target());
  if (camera.has_up() && glm::length(toGlm(camera.up())) > 0.0f) orbit.up = glm::normalize(toGlm(camera.up()));
  const glm::vec3 offset = toGlm(camera.eye()) - orbit.target;
  orbit.radius = std::max(1e-3f, glm::length(offset));
  orbit.yaw = std::atan2(offset.x, offset.z);
  orbit.pitch = std::asin(std::clamp(offset.y / orbit.radius, -1.0f, 1.0f));
  if (camera.fov_degrees() > 0.0f) orbit.fovDegrees = camera.fov_degrees();
  return orbit;
}

glm::vec3 OrbitCamera::eye() const {
  const float c = std::cos(pitch);
  return target + radius * glm::vec3(c * std::sin(yaw), std::sin(pitch), c * std::cos(yaw));
}

void OrbitCamera::orbit(float yawRadians, float pitchRadians) {
  yaw += yawRadians;
  pitch = std::clamp(pitch + pitchRadians, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::zoom(float factor) { radius = std::clamp(radius * factor, 1e-3f, 1e5f); }

void OrbitCamera::pan(float right, float upward) {
  const glm::vec3 forward = glm::normalize(target - eye());
  const glm::vec3 rightAxis = glm::normalize(glm::cross(forward, up));
  const glm::vec3 upAxis = glm::cross(rightAxis, forward);
  target += right * rightAxis + upward * upAxis;
}

v1::ClientMessage OrbitCamera::message(std::uint64_t sequence, double clientTimeMs) const {
  v1::ClientMessage message;
  v1::CameraUpdate& camera = *message.mutable_camera() = protocol::cameraUpdate(eye(), target, up, fovDegrees);
  camera.set_sequence(sequence);
  camera.set_client_time_ms(clientTimeMs);
  return message;
}

}  // namespace specula::client
