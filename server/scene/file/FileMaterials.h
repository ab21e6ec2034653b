#pragma once
// A scene file's "materials" entries and the image files their textures come from.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <utility>

#include "scene/JsonNode.h"
#include "scene/Material.h"
#include "scene/NameIndex.h"
#include "scene/Scene.h"
#include "scene/Texture.h"

namespace specula::scene::file {

// Textures by the file and wrap mode that made them, so materials sharing an image decode it once.
struct TextureFiles {
  std::map<std::pair<std::filesystem::path, TextureWrap>, std::uint32_t> loaded;
  std::size_t texels = 0;  // in the scene's textures, counted against kMaxTexelsPerScene
};

// A material, its name added to `materials`; a texture it names (an image inside `baseDir`) joins
// `scene`'s textures unless `textures` already holds it. "color" may be left out when a texture gives the
// colour (it then multiplies white).
Material readMaterial(const JsonNode& node, NameIndex& materials, const std::filesystem::path& baseDir, Scene& scene,
                      TextureFiles& textures);

}  // namespace specula::scene::file
