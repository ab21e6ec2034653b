#pragma once
// Meshes that change shape, on the CPU: morph targets weighted, then linear blend skinning by the joints
// of a skin. Loading bakes still deformations with it and the reference ray tracer poses each frame with
// it; the renderer deforms on the GPU (shaders/deform/deform.comp), its own code. And a box that holds the
// deformed mesh without deforming it.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "math/Bounds.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

namespace specula::scene {

// Morph targets a mesh may have, and the largest displacement component: with weights bounded too, a
// morphed vertex stays finite. Files beyond either are refused.
inline constexpr std::size_t kMaxMorphTargets = 64;
inline constexpr float kMaxMorphDisplacement = 1e9f;
// Joints a skin may have.
inline constexpr std::size_t kMaxSkinJoints = 1024;

// `mesh`'s vertices with its morph targets weighted by `weights` (one per target, or none: the rest
// shape), then skinned by `joints` (one matrix per joint of its skin, or none: not skinned). Normals
// follow each vertex's blended matrix by its inverse transpose.
std::vector<Vertex> deformedVertices(const Mesh& mesh, std::span<const float> weights,
                                     std::span<const glm::mat4> joints);
// Deforms `mesh` for good and drops its targets and influences.
void bakeDeformation(Mesh& mesh, std::span<const float> weights, std::span<const glm::mat4> joints);

// What deformedBounds needs of a mesh, found once.
struct DeformationExtents {
  math::Bounds rest;
  std::vector<math::Bounds> targets;  // the box of each target's displacements
  std::vector<math::Bounds> joints;   // per joint of the skin: the rest box of the vertices it moves
};
DeformationExtents deformationExtents(const Mesh& mesh, std::size_t jointCount);
// A box holding every vertex of the mesh deformed by `weights` and `joints`, in O(targets + joints):
// morphing widens the rest box by each target's weighted extremes; a skinned vertex lies between its
// joints' images of it, so inside the union of each joint's box (widened alike) carried by that joint.
math::Bounds deformedBounds(const DeformationExtents& extents, std::span<const float> weights,
                            std::span<const glm::mat4> joints);

// The matrices taking a mesh on rig node `meshNode`, skinned by `skin`, to that node's space, one per joint:
// node world⁻¹ · joint world · inverse bind, for the node transforms `world` (NodeRig::worldAt).
std::vector<glm::mat4> skinMatrices(const RigSkin& skin, const std::vector<glm::dmat4>& world, std::uint32_t meshNode);

// Whether object `object` of `scene` changes shape with time (its morph weights animate, or a skin poses it).
bool deforms(const Scene& scene, std::size_t object);

// A message naming what is wrong with `mesh`'s morph targets or influences (counts, values, joints at or
// beyond `jointCount`), or nullopt.
std::optional<std::string> deformationProblem(const Mesh& mesh, std::size_t jointCount);

}  // namespace specula::scene
