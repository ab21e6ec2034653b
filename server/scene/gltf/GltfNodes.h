#pragma once
// A glTF scene's node tree: each node's own transform, composed down the tree, and what a node carries.
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>

#include "base/Result.h"
#include "scene/NodeRig.h"

namespace specula::scene::gltf {

// A camera or light met in the node tree: its index in the file, its node's world transform, and the
// rig node that moves it if an animation does.
struct NodeAttachment {
  int index = -1;
  glm::dmat4 world{1.0};
  std::optional<std::uint32_t> rigNode;
};

// A node as the walk meets it: its index, its parent's, its own transform (no parent set) and its world one.
struct VisitedNode {
  std::size_t index = 0;
  std::optional<std::size_t> parent;
  RigNode rest;
  glm::dmat4 world{1.0};
};

// Node `index`'s own transform: its matrix, or its translation, rotation and scale; refuses one not finite
// or not well formed.
Result<RigNode> restTransform(const tinygltf::Node& node, std::size_t index);

// The light a node carries through KHR_lights_punctual, if any.
std::optional<int> nodeLight(const tinygltf::Node& node);

// Visits the nodes of scene `sceneIndex` depth first, in the file's order (a parent before its children),
// each with its world transform (TRS or matrix, composed down the tree). Refuses a node index out of range, a transform
// that is not finite or not well formed, and a node reached twice (a cycle or a second parent); a failed visit ends the
// walk.
Status walkNodeTree(const tinygltf::Model& model, std::size_t sceneIndex,
                    const std::function<Status(const VisitedNode& node)>& visit);

}  // namespace specula::scene::gltf
