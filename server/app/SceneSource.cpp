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

std::vector<OptionSpec> sceneChoiceOptions() {
  return {{"gltf-scene", "N", "with a glTF --scene: which of its scenes (index)", "the file's default scene"},
          {"camera", "N", "with a glTF --scene: which of its cameras (index)",
           "the first on a node, else a view of everything"},
          {"animation", "all|none|NAME|INDEX",
           "with a glTF --scene: which of its animations play: all, none, or one by name or index", "all"},
          {"environment", "sky|none|FILE",
           "what the background and every mirror show where rays meet nothing: the procedural sky, the scene's "
           "background colour, or an equirectangular PNG, JPEG or Radiance .hdr image",
           "the scene's (sky for glTF files and scene files without a background)"}};
}

std::vector<OptionSpec> withSceneChoice(std::vector<OptionSpec> specs) {
  for (OptionSpec& spec : sceneChoiceOptions()) specs.push_back(std::move(spec));
  return specs;
}

Result<SceneChoice> parseSceneChoice(const CommandLine& options) {
  SceneChoice choice;
  for (const char* name : {"gltf-scene", "camera"}) {
    if (!options.has(name)) continue;
    auto index = options.integer(name, 0, kMaxGltfIndex);
    if (!index) return Error{index.error()};
    (std::string(name) == "camera" ? choice.gltf.camera : choice.gltf.scene) = static_cast<std::size_t>(*index);
  }
  if (options.has("animation")) choice.gltf.animation = options.text("animation");
  if (options.has("environment")) choice.environment = options.text("environment");
  return choice;
}

namespace {

Result<scene::Scene> readScene(const std::string& nameOrFile, const scene::GltfSceneChoice& choice) {
  if (auto builtin = scene::makeBuiltinScene(nameOrFile)) return std::move(*builtin);
  std::error_code error;
  if (!std::filesystem::exists(nameOrFile, error)) {
    std::string names;
    for (std::string_view name : scene::builtinSceneNames()) names += (names.empty() ? "" : ", ") + std::string(name);
    return Error{"scene '" + nameOrFile + "' is neither a built-in scene (" + names + ") nor an existing file"};
  }
  if (scene::isGltfFile(nameOrFile)) {
    auto imported = scene::importGltfScene(nameOrFile, choice);
    if (!imported) return Error{imported.error()};
    return std::move(imported->scene);
  }
  return scene::loadSceneFile(nameOrFile);
}

}  // namespace

Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile, const SceneChoice& choice) {
  Result<scene::Scene> loaded = readScene(nameOrFile, choice.gltf);
  if (!loaded) return Error{loaded.error()};
  if (choice.environment)
    if (Status chosen = scene::chooseEnvironment(*loaded, *choice.environment); !chosen)
      return Error{"--environment: " + chosen.error()};
  for (const std::string& note : loaded->notes)
    std::fprintf(stderr, "specula: %s: %s\n", nameOrFile.c_str(), note.c_str());
  return std::make_shared<const scene::Scene>(std::move(loaded).value());
}

}  // namespace specula::app
