#pragma once
// The view of an imported glTF scene: a camera from its node tree, or one framing the whole scene.
#include <tiny_gltf.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/gltf/GltfNodes.h"

namespace specula::scene::gltf {

// Sets the scene's camera from `wanted` (else the first of `cameras`, as met in scene `sceneIndex`'s
// node tree), or a view framing the scene's objects when there is none or it is not perspective.
Status placeCamera(const tinygltf::Model& model, const std::vector<NodeAttachment>& cameras,
                   std::optional<std::size_t> wanted, std::size_t sceneIndex, ImportedGltfScene& imported);

}  // namespace specula::scene::gltf
