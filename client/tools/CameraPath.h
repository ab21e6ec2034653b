#pragma once
// Keyframed camera (and optional scene time) paths for specula-path, read from JSON or CSV.
//   JSON: {"keys": [{"time": 0, "eye": [x,y,z], "target": [x,y,z], "up": [0,1,0], "fov": 45, "scene_time": 0}, ...]}
//   CSV:  header time,eye_x,eye_y,eye_z,target_x,target_y,target_z[,up_x,up_y,up_z][,fov][,scene_time]
// Times in seconds, strictly increasing; positions in world metres. Between keys everything is linear.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/Result.h"

namespace specula::client {

struct PathKey {
  double time = 0.0;
  glm::vec3 eye{0.0f, 0.0f, 5.0f}, target{0.0f}, up{0.0f, 1.0f, 0.0f};
  float fovDegrees = 45.0f;
  std::optional<double> sceneTime;  // seconds; set on every key or none
};

struct CameraPath {
  std::vector<PathKey> keys;  // at least one
  double duration() const { return keys.back().time - keys.front().time; }
  PathKey at(double time) const;  // clamped to the first and last key
};

// Parses a path; the error names the key or line and what is wrong with it.
Result<CameraPath> parseCameraPathJson(const std::string& text);
Result<CameraPath> parseCameraPathCsv(const std::string& text);
// Reads FILE by its extension (.json or .csv).
Result<CameraPath> loadCameraPath(const std::string& file);

}  // namespace specula::client
