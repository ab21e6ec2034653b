#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/CommandLine.h"
#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/Scene.h"

namespace specula::app {

// How a --scene is taken: which scene and camera of a glTF file, and what rays that meet nothing see.
struct SceneChoice {
  scene::GltfSceneChoice gltf;
  std::optional<std::string> environment;  // "sky", "none" or an image file; unset: the scene's own
};

// What --scene takes, for every command's option table.
inline constexpr const char* kSceneOptionHelp =
    "built-in scene name (see `specula scenes`), glTF file (.gltf, .glb) or JSON scene file";

// --gltf-scene, --camera, --animation and --environment: how a command takes its --scene.
std::vector<OptionSpec> sceneChoiceOptions();
// `specs` and the scene choice options, for a command's option table; and their values.
std::vector<OptionSpec> withSceneChoice(std::vector<OptionSpec> specs);
Result<SceneChoice> parseSceneChoice(const CommandLine& options);

// Resolves --scene: a built-in scene's name, a glTF file (.gltf or .glb: its scene, chosen by
// `choice`) or a JSON scene file; the scene's notes (what was read differently) go to stderr.
Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile, const SceneChoice& choice = {});

}  // namespace specula::app
