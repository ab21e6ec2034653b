#include "scene/gltf/GltfNodes.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace specula::scene::gltf {

namespace {}  // namespace

Result<RigNode> restTransform(const tinygltf::Node& node, std::size_t index) {
  const std::string where = "node " + std::to_string(index) + ": ";
  const auto finite = [](const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  };
  if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale))
    return Error{where + "its transform is not finite"};
  RigNode rest;
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) return Error{where + "matrix must have 16 numbers"};
    glm::dmat4 m;
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row)
        m[column][row] = node.matrix[static_cast<std::size_t>(4 * column + row)];  // column-major
    rest.matrix = m;
    return rest;
  }
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) return Error{where + "translation must have 3 numbers"};
    rest.translation = glm::dvec3(node.translation[0], node.translation[1], node.translation[2]);
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) return Error{where + "rotation must be a quaternion of 4 numbers (x, y, z, w)"};
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (glm::length(q) < 1e-6) return Error{where + "rotation is a zero quaternion"};
    rest.rotation = glm::normalize(q);
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) return Error{where + "scale must have 3 numbers"};
    rest.scale = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
  }
  return rest;
}

std::optional<int> nodeLight(const tinygltf::Node& node) {
  const auto extension = node.extensions.find("KHR_lights_punctual");
  if (extension == node.extensions.end() || !extension->second.IsObject() || !extension->second.Has("light"))
    return std::nullopt;
  const tinygltf::Value& light = extension->second.Get("light");
  return light.IsInt() ? std::optional<int>(light.GetNumberAsInt()) : std::nullopt;
}

Status walkNodeTree(const tinygltf::Model& model, std::size_t sceneIndex,
                    const std::function<Status(const VisitedNode& node)>& visit) {
  struct Pending {
    int node;
    std::optional<std::size_t> parent;
    glm::dmat4 parentWorld;
  };
  std::vector<Pending> pending;
  const std::vector<int>& roots = model.scenes[sceneIndex].nodes;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.push_back({*it, std::nullopt, glm::dmat4(1.0)});
  std::vector<bool> reached(model.nodes.size(), false);
  while (!pending.empty()) {
    const Pending next = pending.back();
    pending.pop_back();
    if (next.node < 0 || static_cast<std::size_t>(next.node) >= model.nodes.size())
      return Error{"scene " + std::to_string(sceneIndex) + " refers to node " + std::to_string(next.node) +
                   ", but the file has " + std::to_string(model.nodes.size())};
    const auto index = static_cast<std::size_t>(next.node);
    if (reached[index])
      return Error{"node " + std::to_string(index) +
                   " is reached twice: the node tree has a cycle or a node with two parents"};
    reached[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    Result<RigNode> rest = restTransform(node, index);
    if (!rest) return Error{rest.error()};
    const VisitedNode visiting{index, next.parent, rest.value(), next.parentWorld * rest->local()};
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
      pending.push_back({*child, index, visiting.world});
    if (Status visited = visit(visiting); !visited) return visited;
  }
  return {};
}

}  // namespace specula::scene::gltf
