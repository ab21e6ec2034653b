#include "scene/SceneLoader.h"

#include <optional>
#include <string>
#include <utility>

#include "scene/AssetFiles.h"
#include "scene/JsonNode.h"
#include "scene/SceneChecks.h"
#include "scene/StrictJson.h"
#include "scene/file/FileScene.h"

namespace specula::scene {

namespace fs = std::filesystem;

Result<Scene> loadSceneFile(const fs::path& file) {
  Result<std::string> text = readBoundedFile(file, kMaxSceneFileBytes);
  if (!text) return Error{text.error()};
  return parseScene(text.value(), file.parent_path(), file.string());
}

Result<Scene> parseScene(std::string_view json, const fs::path& baseDir, std::string_view sourceName) {
  const std::string source(sourceName);
  if (json.size() > kMaxSceneFileBytes)
    return Error{source + ": " + std::to_string(json.size()) + " bytes, more than the limit of " +
                 std::to_string(kMaxSceneFileBytes)};
  Result<nlohmann::json> document = parseStrictJson(json);
  if (!document) return Error{source + ": " + document.error()};
  std::optional<Scene> scene;
  try {
    scene = file::readScene(JsonNode(document.value(), "$"), baseDir, fs::path(source).stem().string());
  } catch (const JsonNode::Failure& failure) {
    return Error{source + ": " + failure.message};
  }
  if (auto problem = sceneProblem(*scene)) return Error{source + ": " + *problem};
  return *std::move(scene);
}

}  // namespace specula::scene
