#pragma once
// glTF materials and their base colour textures as the scene's own, converted as primitives first use them.
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/Scene.h"
#include "scene/gltf/GltfImages.h"

namespace specula::scene::gltf {

// A material in the scene, and whether the mirror rule makes it chrome (a mirror, on a closed mesh).
struct SceneMaterial {
  std::uint32_t index = 0;
  bool chrome = false;
};

// Refuses a rule naming a material the file lacks: a typo that would silently change nothing.
Status checkMirrorRuleNames(const tinygltf::Model& model, const GltfMirrorRule& rule);

// Adds each glTF material to the scene once, when a primitive first uses it; a base colour texture
// pairs an image with a sampler, one scene texture per pair used. What is read differently from the
// file goes to `notes`.
class MaterialTable {
 public:
  MaterialTable(const tinygltf::Model& model, const DecodedImages& images, const GltfMirrorRule& rule, Scene& scene,
                std::vector<std::string>& notes);

  // The file's material `index`; -1 (none) gets glTF's default, a light grey here.
  Result<SceneMaterial> materialOf(int index);

 private:
  Result<std::optional<std::uint32_t>> textureOf(const tinygltf::TextureInfo& info, std::size_t material);

  const tinygltf::Model& model_;
  const DecodedImages& images_;
  const GltfMirrorRule& rule_;
  Scene& scene_;
  std::vector<std::string>& notes_;
  std::map<int, SceneMaterial> materials_;                                       // by glTF material index
  std::map<std::tuple<int, TextureWrap, TextureWrap>, std::uint32_t> textures_;  // image and wraps → scene texture
};

}  // namespace specula::scene::gltf
