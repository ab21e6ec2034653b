#include "scene/file/FileMaterials.h"

#include <optional>
#include <string>

#include "base/Result.h"
#include "scene/AssetFiles.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

namespace {

namespace fs = std::filesystem;

// "file.png" or {"file": "file.png", "wrap": "repeat" | "clamp" | "mirror"}: an image beside the scene.
std::uint32_t readTexture(const JsonNode& node, const fs::path& baseDir, Scene& scene, TextureFiles& files) {
  const JsonNode file = node.isString() ? node : node.at("file");
  TextureWrap wrap = TextureWrap::Repeat;
  if (!node.isString()) {
    node.expectObject({"file", "wrap"});
    if (const auto mode = node.find("wrap")) {
      if (mode->string() == "clamp") wrap = TextureWrap::ClampToEdge;
      else if (mode->string() == "mirror") wrap = TextureWrap::MirroredRepeat;
      else if (mode->string() != "repeat")
        mode->fail("unknown wrap " + JsonNode::quoted(mode->string()) + "; use repeat, clamp or mirror");
    }
  }
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  if (const auto known = files.loaded.find({*path, wrap}); known != files.loaded.end()) return known->second;
  Result<std::string> bytes = readBoundedFile(*path, kMaxAssetFileBytes);
  if (!bytes) file.fail(bytes.error());
  Result<Texture> texture = decodeTexture(*bytes, path->filename().string());
  if (!texture) file.fail(texture.error());
  if ((files.texels += texture->texelCount()) > kMaxTexelsPerScene)
    file.fail("the scene's textures hold more than " + std::to_string(kMaxTexelsPerScene) +
              " texels with this one; use smaller images");
  texture->wrapU = texture->wrapV = wrap;
  scene.textures.push_back(std::move(texture).value());
  return files.loaded[{*path, wrap}] = static_cast<std::uint32_t>(scene.textures.size() - 1);
}

}  // namespace

Material readMaterial(const JsonNode& node, NameIndex& materials, const fs::path& baseDir, Scene& scene,
                      TextureFiles& textures) {
  node.expectObject({"name", "color", "unlit", "checker", "reflectivity", "texture"});
  Material material;
  material.name = materials.add(node.at("name"));
  const std::optional<JsonNode> texture = node.find("texture");
  if (texture) material.texture = readTexture(*texture, baseDir, scene, textures);
  material.baseColor = texture && !node.find("color") ? glm::vec3(1.0f) : readColor(node.at("color"));
  if (const auto unlit = node.find("unlit")) material.unlit = unlit->boolean();
  if (const auto reflectivity = node.find("reflectivity"))
    material.reflectivity = static_cast<float>(reflectivity->inRange(0.0, 1.0));
  if (const auto checker = node.find("checker")) {
    checker->expectObject({"color", "cells_per_unit"});
    material.checker = Checker{readColor(checker->at("color")), 1.0f};
    if (const auto cells = checker->find("cells_per_unit"))
      material.checker->cellsPerUnit = static_cast<float>(cells->positive());
  }
  return material;
}

}  // namespace specula::scene::file
