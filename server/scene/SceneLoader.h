#pragma once
// Scene files: strict JSON ("specula_scene": 1) naming meshes, materials, objects, lights, animations
// and a camera. The format is documented in docs/scenes.md, "Scene files".
#include <filesystem>
#include <string_view>

#include "base/Result.h"
#include "scene/Scene.h"

namespace specula::scene {

inline constexpr int kSceneFormatVersion = 1;

// Reads and parses a scene file (at most kMaxSceneFileBytes); asset paths in it are relative to its folder.
Result<Scene> loadSceneFile(const std::filesystem::path& file);

// Parses scene JSON. Mesh files resolve inside `baseDir`. Every error message starts with `sourceName`,
// then the JSONPath of the offending value and the problem, e.g.
//   scenes/a.json: $.objects[2].material: unknown material "steel" (known: "floor", "chrome")
// A returned scene satisfies sceneProblem() and the vertex and triangle limits of SceneChecks.h.
Result<Scene> parseScene(std::string_view json, const std::filesystem::path& baseDir, std::string_view sourceName);

}  // namespace specula::scene
