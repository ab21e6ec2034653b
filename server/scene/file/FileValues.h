#pragma once
// Values a scene file writes in many places: colours, directions, rotations, scales, transforms, cameras.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "math/Camera.h"
#include "math/Transform.h"
#include "scene/JsonNode.h"

namespace specula::scene::file {

// sRGB "#rrggbb" or [r, g, b] in [0, 1], returned as linear RGB.
glm::vec3 readColor(const JsonNode& node);

// Any non-zero vector, normalized.
glm::vec3 readDirection(const JsonNode& node);

// [x, y, z] with every component greater than 0.
glm::vec3 readPositiveVec3(const JsonNode& node);

// {"axis": [x, y, z], "degrees": a} or {"quaternion": [x, y, z, w]}; the quaternion is normalized.
glm::quat readRotation(const JsonNode& node);

// A positive number (uniform) or [x, y, z] of positive numbers; mirrored (negative) scales would flip winding.
glm::vec3 readScale(const JsonNode& node);

// Applies the "translation", "rotation" and "scale" keys present in `node` to `transform`.
math::Transform readTransform(const JsonNode& node, math::Transform transform);

// "eye" and "target" (required), "up" and "fov" (defaulting to `camera`'s); the caller checks the keys.
math::Camera readCamera(const JsonNode& node, math::Camera camera);

}  // namespace specula::scene::file
