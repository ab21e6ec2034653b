#include "app/SceneSource.h"

#include <cstdio>
#include <filesystem>

#include "scene/AssetFiles.h"
#include "scene/SceneLoader.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

namespace {

constexpr int kMaxGltfIndex = 1 << 20;

}  // namespace

std::vector<OptionSpec> gltfSceneOptions() {
  return {{"gltf-scene", "N", "with a glTF --scene: which of its scenes (index)", "the file's default scene"},
          {"camera", "N", "with a glTF --scene: which of its cameras (index)",
           "the first on a node, else a view of everything"}};
}

Result<scene::GltfSceneChoice> parseGltfSceneOptions(const CommandLine& options) {
  scene::GltfSceneChoice choice;
  for (const char* name : {"gltf-scene", "camera"}) {
    if (!options.has(name)) continue;
    auto index = options.integer(name, 0, kMaxGltfIndex);
    if (!index) return Error{index.error()};
    (std::string(name) == "camera" ? choice.camera : choice.scene) = static_cast<std::size_t>(*index);
  }
  return choice;
}

Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile,
                                                      const scene::GltfSceneChoice& choice) {
  if (auto builtin = scene::makeBuiltinScene(nameOrFile))
    return std::make_shared<const scene::Scene>(std::move(*builtin));
  std::error_code error;
  if (!std::filesystem::exists(nameOrFile, error)) {
    std::string names;
    for (std::string_view name : scene::builtinSceneNames()) names += (names.empty() ? "" : ", ") + std::string(name);
    return Error{"scene '" + nameOrFile + "' is neither a built-in scene (" + names + ") nor an existing file"};
  }
  std::shared_ptr<const scene::Scene> loaded;
  if (scene::isGltfFile(nameOrFile)) {
    auto imported = scene::importGltfScene(nameOrFile, choice);
    if (!imported) return Error{imported.error()};
    loaded = std::make_shared<const scene::Scene>(std::move(imported->scene));
  } else {
    auto file = scene::loadSceneFile(nameOrFile);
    if (!file) return Error{file.error()};
    loaded = std::make_shared<const scene::Scene>(std::move(file.value()));
  }
  for (const std::string& note : loaded->notes)
    std::fprintf(stderr, "specula: %s: %s\n", nameOrFile.c_str(), note.c_str());
  return loaded;
}

}  // namespace specula::app
