#include "app/SceneSource.h"

#include <filesystem>

#include "scene/SceneLoader.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::app {

Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile) {
  if (auto builtin = scene::makeBuiltinScene(nameOrFile)) return std::make_shared<const scene::Scene>(std::move(*builtin));
  std::error_code error;
  if (!std::filesystem::exists(nameOrFile, error)) {
    std::string names;
    for (std::string_view name : scene::builtinSceneNames()) names += (names.empty() ? "" : ", ") + std::string(name);
    return Error{"scene '" + nameOrFile + "' is neither a built-in scene (" + names + ") nor an existing file"};
  }
  auto loaded = scene::loadSceneFile(nameOrFile);
  if (!loaded) return Error{loaded.error()};
  return std::make_shared<const scene::Scene>(std::move(loaded.value()));
}

}  // namespace specula::app
