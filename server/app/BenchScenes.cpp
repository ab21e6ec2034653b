#include "app/BenchScenes.h"

#include <sstream>

#include "app/SceneSource.h"

namespace specula::app {

std::vector<std::string> sceneList(const CommandLine& options, const std::vector<std::string>& defaults) {
  std::vector<std::string> names;
  if (!options.has("scenes")) return defaults;
  std::stringstream list(options.text("scenes"));
  for (std::string name; std::getline(list, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

Result<std::vector<std::shared_ptr<const scene::Scene>>> loadScenes(const std::vector<std::string>& names,
                                                                    const SceneChoice& choice) {
  if (names.empty()) return Error{"--scenes names no scene"};
  std::vector<std::shared_ptr<const scene::Scene>> scenes;
  for (const std::string& name : names) {
    auto loaded = loadScene(name, choice);
    if (!loaded) return Error{loaded.error()};
    scenes.push_back(*loaded);
  }
  return scenes;
}

}  // namespace specula::app
