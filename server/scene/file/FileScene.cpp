#include "scene/file/FileScene.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/AssetFiles.h"
#include "scene/Environment.h"
#include "scene/SceneChecks.h"
#include "scene/SceneLoader.h"
#include "scene/file/FileAnimations.h"
#include "scene/file/FileIncludes.h"
#include "scene/file/FileLights.h"
#include "scene/file/FileLimits.h"
#include "scene/file/FileMaterials.h"
#include "scene/file/FileMeshes.h"
#include "scene/file/FileNames.h"
#include "scene/file/FileObjects.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

namespace fs = std::filesystem;

namespace {

// "sky", "none" (the background colour) or {"image": "file.jpg"}: an equirectangular PNG, JPEG or .hdr beside the
// scene.
void readEnvironment(const JsonNode& node, const fs::path& baseDir, Scene& scene) {
  if (node.isString()) {
    const auto named = namedEnvironment(node.string());
    if (!named)
      node.fail("unknown environment " + JsonNode::quoted(node.string()) +
                "; use \"sky\", \"none\" or {\"image\": \"file.jpg\"}");
    scene.environment = *named;
    return;
  }
  node.expectObject({"image"});
  const JsonNode file = node.at("image");
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  if (Status used = useEnvironmentImage(scene, *path); !used) file.fail(used.error());
}

}  // namespace

Scene readScene(const JsonNode& root, const fs::path& baseDir, std::string defaultName) {
  // The version comes first so a newer file fails on its version, not on keys this build does not know.
  const std::optional<JsonNode> version = root.find("specula_scene");
  if (!version) root.fail("missing \"specula_scene\": " + std::to_string(kSceneFormatVersion) + ", the format version");
  if (const std::int64_t number =
          version->integer(std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max());
      number != kSceneFormatVersion)
    version->fail("unsupported scene format version " + std::to_string(number) + "; this build reads version " +
                  std::to_string(kSceneFormatVersion));
  root.expectObject({"specula_scene", "name", "background", "environment", "ambient", "camera", "meshes", "materials",
                     "objects", "includes", "lights", "animations"});
  Scene scene;
  const std::optional<JsonNode> name = root.find("name");
  scene.name = name ? name->string() : std::move(defaultName);
  const std::optional<JsonNode> background = root.find("background");
  if (background) scene.background = readColor(*background);
  if (const auto ambient = root.find("ambient")) scene.ambient = readColor(*ambient);
  const JsonNode camera = root.at("camera");
  camera.expectObject({"eye", "target", "up", "fov"});
  scene.camera = readCamera(camera, math::Camera{});

  Names names;
  // A scene of included glTF files alone needs no meshes, materials or objects of its own.
  const std::optional<JsonNode> includes = root.find("includes");
  const auto entities = [&](std::string_view key) {
    const std::optional<JsonNode> list = root.find(key);
    if (!list && !includes) root.at(key);  // fails: the key is required
    return list ? list->array(includes ? 0 : 1, kMaxEntities) : std::vector<JsonNode>{};
  };
  std::size_t meshVertices = 0;
  for (const JsonNode& node : entities("meshes")) {
    scene.meshes.push_back(readMesh(node, baseDir, names.meshes));
    if ((meshVertices += scene.meshes.back().vertices.size()) > kMaxVerticesPerScene)
      node.fail("meshes hold " + std::to_string(meshVertices) + " vertices so far, more than the scene limit of " +
                std::to_string(kMaxVerticesPerScene));
  }
  TextureFiles textures;
  for (const JsonNode& node : entities("materials"))
    scene.materials.push_back(readMaterial(node, names.materials, baseDir, scene, textures));
  std::size_t vertices = 0, triangles = 0;
  for (const JsonNode& node : entities("objects")) {
    scene.objects.push_back(readObject(node, names));
    const Mesh& mesh = scene.meshes[scene.objects.back().mesh];
    if ((vertices += mesh.vertices.size()) > kMaxVerticesPerScene ||
        (triangles += mesh.triangleCount()) > kMaxTrianglesPerScene)
      node.fail("objects so far draw " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                " triangles, more than the scene limits of " + std::to_string(kMaxVerticesPerScene) + " and " +
                std::to_string(kMaxTrianglesPerScene));
  }
  if (includes) {
    for (const JsonNode& node : includes->array(1, kMaxIncludes)) readInclude(node, baseDir, scene, names, textures);
    if (scene.vertexCount() > kMaxVerticesPerScene || scene.triangleCount() > kMaxTrianglesPerScene)
      includes->fail("with its includes the scene draws " + std::to_string(scene.vertexCount()) + " vertices and " +
                     std::to_string(scene.triangleCount()) + " triangles, more than the limits of " +
                     std::to_string(kMaxVerticesPerScene) + " and " + std::to_string(kMaxTrianglesPerScene));
  }
  // The sky unless the file asks for something else; a file that sets only a background colour keeps it.
  if (const auto environment = root.find("environment")) readEnvironment(*environment, baseDir, scene);
  else if (!background) scene.environment.kind = EnvironmentKind::Sky;
  if (const auto lights = root.find("lights"))
    for (const JsonNode& node : lights->array(0, kMaxLights)) scene.lights.push_back(readLight(node));
  if (const auto animations = root.find("animations"))
    for (const JsonNode& node : animations->array(0, kMaxEntities))
      scene.animations.push_back(readAnimation(node, names, scene));
  return scene;
}

}  // namespace specula::scene::file
