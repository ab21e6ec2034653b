#include "scene/ParametricMesh.h"

#include <algorithm>

namespace specula::scene {

Mesh parametricMesh(std::string name, std::vector<math::BezierPatch> patches, int segments) {
  const math::PatchGrid grid = math::tessellatePatchGrid(patches, segments);
  Mesh mesh{std::move(name), {}, grid.indices, std::move(patches), segments};
  mesh.vertices.reserve(grid.positions.size());
  for (std::size_t i = 0; i < grid.positions.size(); ++i)
    mesh.vertices.push_back({glm::vec3(grid.positions[i]), glm::vec3(grid.normals[i]), glm::vec2(grid.uvs[i])});
  // Each triangle's centroid against the exact surface at its (u, v) centroid: where a flat piece
  // strays farthest from a smooth surface, near enough.
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t a = grid.indices[3 * t], b = grid.indices[3 * t + 1], c = grid.indices[3 * t + 2];
    const glm::dvec2 uv = (grid.uvs[a] + grid.uvs[b] + grid.uvs[c]) / 3.0;
    const glm::dvec3 centroid = (grid.positions[a] + grid.positions[b] + grid.positions[c]) / 3.0;
    const glm::dvec3 exact = mesh.patches[patchOfTriangle(mesh, t)].sample(uv.x, uv.y).position;
    mesh.gridDeviation = std::max(mesh.gridDeviation, glm::length(exact - centroid));
  }
  return mesh;
}

}  // namespace specula::scene
