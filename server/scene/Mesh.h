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

  std::size_t triangleCount() const { return indices.size() / 3; }
};

}  // namespace specula::scene
