#pragma once
// A glTF skin as the rig's: its joints as rig nodes and their inverse bind matrices, checked and named by
// JSONPath where broken.
#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "scene/NodeRig.h"

namespace specula::scene::gltf {

// Skin `skin` of the file, its joints named by `rigNode` (file node → rig node; every joint must be in the
// scene drawn), its inverse bind matrices the identity where the file gives none.
Result<RigSkin> readSkin(const tinygltf::Model& model, std::size_t skin,
                         const std::vector<std::optional<std::uint32_t>>& rigNode);

}  // namespace specula::scene::gltf
