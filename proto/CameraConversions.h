#pragma once
// GLM vectors to and from the protocol's Vec3, and a CameraUpdate from its parts: one place for the
// server and every client.
#include <glm/glm.hpp>

#include "specula.pb.h"

namespace specula::protocol {

glm::vec3 toGlm(const v1::Vec3& v);
v1::Vec3 toProto(const glm::vec3& v);
// eye, target, up and fov set; sequence and client time left for the sender.
v1::CameraUpdate cameraUpdate(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fovDegrees);

}  // namespace specula::protocol
