#pragma once
// A glTF scene's node tree: each node's own transform, composed down the tree, and what a node carries.
#include <tiny_gltf.h>

#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <optional>

#include "base/Result.h"

namespace specula::scene::gltf {

// A camera or light met in the node tree: its index in the file and its node's world transform.
struct NodeAttachment {
  int index = -1;
  glm::dmat4 world{1.0};
};

// The light a node carries through KHR_lights_punctual, if any.
std::optional<int> nodeLight(const tinygltf::Node& node);

// Visits the nodes of scene `sceneIndex` depth first, in the file's order, each with its world transform
// (TRS or matrix, composed down the tree). Refuses a node index out of range, a transform that is not
// finite or not well formed, and a node reached twice (a cycle or a second parent); a failed visit ends the walk.
Status walkNodeTree(const tinygltf::Model& model, std::size_t sceneIndex,
                    const std::function<Status(std::size_t node, const glm::dmat4& world)>& visit);

}  // namespace specula::scene::gltf
