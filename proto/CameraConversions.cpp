#include "CameraConversions.h"

namespace specula::protocol {

glm::vec3 toGlm(const v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

v1::Vec3 toProto(const glm::vec3& v) {
  v1::Vec3 out;
  out.set_x(v.x);
  out.set_y(v.y);
  out.set_z(v.z);
  return out;
}

v1::CameraUpdate cameraUpdate(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovDegrees) {
  v1::CameraUpdate camera;
  *camera.mutable_eye() = toProto(eye);
  *camera.mutable_target() = toProto(target);
  *camera.mutable_up() = toProto(up);
  camera.set_fov_degrees(fovDegrees);
  return camera;
}

}  // namespace specula::protocol
