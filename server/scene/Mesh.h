#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "math/BezierPatch.h"

namespace specula::scene {

struct Vertex {
  glm::vec3 position{0.0f};            // object space, metres
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // object space, unit length
  glm::vec2 uv{0.0f};
};

// Displacements of every vertex that one weight scales (a glTF morph target): the mesh at weights w has
// positions p + Σₖ wₖ·positions[k] and normals normalize(n + Σₖ wₖ·normals[k]).
struct MorphTarget {
  std::vector<glm::vec3> positions;  // one per vertex
  std::vector<glm::vec3> normals;    // one per vertex, or empty: the target leaves normals alone
};

// Four of the joints a skinned mesh's vertices follow (glTF JOINTS_n / WEIGHTS_n): joint indices into the
// skin's list and their weights, one entry per vertex.
struct JointInfluences {
  std::vector<glm::uvec4> joints;
  std::vector<glm::vec4> weights;
};

// An indexed triangle list, counter-clockwise front faces. Shared read-only by every object using it.
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // size is a multiple of 3; every index < vertices.size()
  // Set when the mesh is a parametric surface (scene/ParametricMesh.h): these patches are its exact
  // surface (object space) and the triangles their uniform grid of patchSegments² quads per patch,
  // patch after patch, with uv = (u, v) on the triangle's patch.
  std::vector<math::BezierPatch> patches{};
  int patchSegments = 0;
  // How far the grid's triangles stray from the exact surface (object space; 0 for other meshes): a
  // ray leaving the exact surface can meet the grid's chords within about this of its start.
  double gridDeviation = 0.0;
  // Set only on a mesh whose weights change with time (still weights are applied when loading); each
  // object using it gets its weights from ScenePose::morphWeights.
  std::vector<MorphTarget> morphTargets{};
  // Set only on a skinned mesh: one or two sets of four influences (JOINTS_0/WEIGHTS_0, then _1), every
  // vertex's weights summing to 1. Each object using it gets its joints from ScenePose::jointMatrices.
  std::vector<JointInfluences> influences{};

  std::size_t triangleCount() const { return indices.size() / 3; }
};

}  // namespace specula::scene
