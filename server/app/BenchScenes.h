#pragma once
// --scenes of `specula bench` and `bench tessellation`: the names, then every scene loaded.
#include <memory>
#include <string>
#include <vector>

#include "base/CommandLine.h"
#include "app/SceneSource.h"
#include "base/Result.h"
#include "scene/Scene.h"

namespace specula::app {

// The comma-separated names --scenes gives, else `defaults`.
std::vector<std::string> sceneList(const CommandLine& options, const std::vector<std::string>& defaults);

// Loads every scene up front, so a typo fails before the long part.
Result<std::vector<std::shared_ptr<const scene::Scene>>> loadScenes(const std::vector<std::string>& names,
                                                                    const SceneChoice& choice = {});

}  // namespace specula::app
