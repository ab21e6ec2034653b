#pragma once
// Reading a glTF asset from a .gltf (JSON) or .glb (binary) file's bytes, with every file it refers
// to confined to its folder and every size bounded before tinygltf allocates it.
#include <tiny_gltf.h>

#include <filesystem>
#include <string_view>

#include "base/Result.h"
#include "scene/gltf/GltfImages.h"

namespace specula::scene::gltf {

// The parsed, checked asset: GLB framing, JSON depth and declared buffer sizes first, then tinygltf
// with file access confined to `folder`; its images go to `images` (decoded if it asks for them).
Result<tinygltf::Model> loadModel(std::string_view bytes, const std::filesystem::path& folder, DecodedImages& images);

}  // namespace specula::scene::gltf
