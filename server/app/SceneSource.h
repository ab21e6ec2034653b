#pragma once
#include <memory>
#include <string>
#include <vector>

#include "base/CommandLine.h"
#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/Scene.h"

namespace specula::app {

// --gltf-scene and --camera: which scene and camera of a glTF file --scene names.
std::vector<OptionSpec> gltfSceneOptions();
Result<scene::GltfSceneChoice> parseGltfSceneOptions(const CommandLine& options);

// Resolves --scene: a built-in scene's name, a glTF file (.gltf or .glb: its scene, chosen by
// `choice`; what the import read differently goes to stderr) or a JSON scene file.
Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile,
                                                      const scene::GltfSceneChoice& choice = {});

}  // namespace specula::app
