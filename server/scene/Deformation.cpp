#include "scene/Deformation.h"

#include <algorithm>
#include <cmath>

#include "math/Transform.h"

namespace specula::scene {

namespace {

bool bounded(const glm::vec3& v) {  // also false for NaN
  return std::abs(v.x) <= kMaxMorphDisplacement && std::abs(v.y) <= kMaxMorphDisplacement &&
         std::abs(v.z) <= kMaxMorphDisplacement;
}

// The box's widening by the weighted targets: p + Σ wₖdₖ lies in [low + Σ min(wₖ·lowₖ, wₖ·highₖ), …].
math::Bounds morphWidening(const DeformationExtents& extents, std::span<const float> weights) {
  math::Bounds widening;
  widening.add(glm::vec3(0.0f));
  for (std::size_t k = 0; k < extents.targets.size() && k < weights.size(); ++k) {
    const math::Bounds& target = extents.targets[k];
    if (target.empty()) continue;
    const glm::vec3 a = weights[k] * target.low, b = weights[k] * target.high;
    widening.low += glm::min(a, b);
    widening.high += glm::max(a, b);
  }
  return widening;
}

}  // namespace

std::vector<Vertex> deformedVertices(const Mesh& mesh, std::span<const float> weights,
                                     std::span<const glm::mat4> joints) {
  std::vector<Vertex> vertices = mesh.vertices;
  std::vector<glm::vec3> normals(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) normals[v] = vertices[v].normal;
  for (std::size_t k = 0; k < mesh.morphTargets.size() && k < weights.size(); ++k) {
    const MorphTarget& target = mesh.morphTargets[k];
    for (std::size_t v = 0; v < vertices.size(); ++v) vertices[v].position += weights[k] * target.positions[v];
    if (!target.normals.empty())
      for (std::size_t v = 0; v < vertices.size(); ++v) normals[v] += weights[k] * target.normals[v];
  }
  const bool skinned = !joints.empty() && !mesh.influences.empty();
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (skinned) {
      glm::mat4 blend(0.0f);
      for (const JointInfluences& set : mesh.influences)
        for (int i = 0; i < 4; ++i)
          if (set.weights[v][i] != 0.0f && set.joints[v][i] < joints.size())
            blend += set.weights[v][i] * joints[set.joints[v][i]];
      vertices[v].position = glm::vec3(blend * glm::vec4(vertices[v].position, 1.0f));
      normals[v] = math::normalMatrix(blend) * normals[v];
    }
    const float length = glm::length(normals[v]);
    if (length > 0.0f && std::isfinite(length)) vertices[v].normal = normals[v] / length;  // else the rest one
  }
  return vertices;
}

void bakeDeformation(Mesh& mesh, std::span<const float> weights, std::span<const glm::mat4> joints) {
  mesh.vertices = deformedVertices(mesh, weights, joints);
  mesh.morphTargets.clear();
  mesh.influences.clear();
}

DeformationExtents deformationExtents(const Mesh& mesh, std::size_t jointCount) {
  DeformationExtents extents;
  for (const Vertex& v : mesh.vertices) extents.rest.add(v.position);
  for (const MorphTarget& target : mesh.morphTargets) {
    math::Bounds& box = extents.targets.emplace_back();
    for (const glm::vec3& d : target.positions) box.add(d);
  }
  if (mesh.influences.empty()) return extents;
  extents.joints.resize(jointCount);
  for (const JointInfluences& set : mesh.influences)
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      for (int i = 0; i < 4; ++i)
        if (set.weights[v][i] != 0.0f) extents.joints[set.joints[v][i]].add(mesh.vertices[v].position);
  return extents;
}

math::Bounds deformedBounds(const DeformationExtents& extents, std::span<const float> weights,
                            std::span<const glm::mat4> joints) {
  if (extents.rest.empty()) return extents.rest;
  const math::Bounds widening = morphWidening(extents, weights);
  const auto widened = [&](const math::Bounds& box) {
    return math::Bounds{box.low + widening.low, box.high + widening.high};
  };
  if (extents.joints.empty() || joints.empty()) return widened(extents.rest);
  math::Bounds bounds;
  for (std::size_t j = 0; j < extents.joints.size() && j < joints.size(); ++j)
    if (!extents.joints[j].empty()) bounds.add(widened(extents.joints[j]).transformed(joints[j]));
  return bounds;
}

std::vector<glm::mat4> skinMatrices(const RigSkin& skin, const std::vector<glm::dmat4>& world, std::uint32_t meshNode) {
  const glm::dmat4 toMesh = glm::inverse(world[meshNode]);
  std::vector<glm::mat4> joints;
  joints.reserve(skin.joints.size());
  for (std::size_t j = 0; j < skin.joints.size(); ++j)
    joints.emplace_back(toMesh * world[skin.joints[j]] * skin.inverseBind[j]);
  return joints;
}

bool deforms(const Scene& scene, std::size_t object) {
  const auto is = [&](const auto& entry) { return entry.object == object; };
  return std::ranges::any_of(scene.rig.morphed, is) || std::ranges::any_of(scene.rig.skinned, is);
}

std::optional<std::string> deformationProblem(const Mesh& mesh, std::size_t jointCount) {
  const std::string what = "mesh '" + mesh.name + "', ";
  if (mesh.morphTargets.size() > kMaxMorphTargets)
    return what + std::to_string(mesh.morphTargets.size()) + " morph targets, more than " +
           std::to_string(kMaxMorphTargets);
  for (std::size_t k = 0; k < mesh.morphTargets.size(); ++k) {
    const MorphTarget& target = mesh.morphTargets[k];
    const std::string where = what + "morph target " + std::to_string(k) + ": ";
    if (target.positions.size() != mesh.vertices.size()) return where + "needs one position displacement per vertex";
    if (!target.normals.empty() && target.normals.size() != mesh.vertices.size())
      return where + "needs one normal displacement per vertex, or none";
    for (const auto* list : {&target.positions, &target.normals})
      for (const glm::vec3& d : *list)
        if (!bounded(d)) return where + "a displacement is not finite or beyond ±1e9";
  }
  if (mesh.influences.size() > 2) return what + "more than two sets of joint influences";
  for (std::size_t s = 0; s < mesh.influences.size(); ++s) {
    const JointInfluences& set = mesh.influences[s];
    const std::string where = what + "joint influences " + std::to_string(s) + ": ";
    if (set.joints.size() != mesh.vertices.size() || set.weights.size() != mesh.vertices.size())
      return where + "need joints and weights for every vertex";
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      for (int i = 0; i < 4; ++i) {
        if (!(set.weights[v][i] >= 0.0f && set.weights[v][i] <= 1.0f)) return where + "a weight is not in [0, 1]";
        if (set.weights[v][i] != 0.0f && set.joints[v][i] >= jointCount)
          return where + "vertex " + std::to_string(v) + " follows joint " + std::to_string(set.joints[v][i]) +
                 ", but its skin has " + std::to_string(jointCount);
      }
  }
  for (std::size_t v = 0; v < mesh.vertices.size() && !mesh.influences.empty(); ++v) {
    float sum = 0.0f;
    for (const JointInfluences& set : mesh.influences) sum += glm::dot(set.weights[v], glm::vec4(1.0f));
    if (std::abs(sum - 1.0f) > 1e-3f) return what + "vertex " + std::to_string(v) + "'s joint weights do not sum to 1";
  }
  return std::nullopt;
}

}  // namespace specula::scene
