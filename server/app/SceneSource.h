#pragma once
#include <memory>
#include <string>

#include "base/Result.h"
#include "scene/Scene.h"

namespace specula::app {

// Resolves --scene: a built-in scene's name, else a path to a JSON scene file.
Result<std::shared_ptr<const scene::Scene>> loadScene(const std::string& nameOrFile);

}  // namespace specula::app
