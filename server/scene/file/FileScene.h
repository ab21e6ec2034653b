#pragma once
// A whole scene file: its version, settings and camera, then each list of entries in order.
#include <filesystem>
#include <string>

#include "scene/JsonNode.h"
#include "scene/Scene.h"

namespace specula::scene::file {

// The scene at `root`, named `defaultName` unless it names itself; asset files resolve inside `baseDir`.
// Fails (JsonNode::Failure) at the first problem; the caller checks the result with sceneProblem().
Scene readScene(const JsonNode& root, const std::filesystem::path& baseDir, std::string defaultName);

}  // namespace specula::scene::file
