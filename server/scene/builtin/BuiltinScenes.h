#pragma once
// Procedural scenes compiled into the server, so it renders something meaningful with no files.
#include <optional>
#include <span>
#include <string_view>

#include "scene/Scene.h"

namespace specula::scene {

// Every built-in scene name in a stable order; the first, "checker-sphere", is the default scene.
std::span<const std::string_view> builtinSceneNames();

// Builds the named scene (it passes sceneProblem()), or nullopt for a name not in builtinSceneNames().
std::optional<Scene> makeBuiltinScene(std::string_view name);

// One line describing the scene, for `specula scenes` and --help; empty for an unknown name.
std::string_view builtinSceneSummary(std::string_view name);

}  // namespace specula::scene
