#include "scene/ParametricMesh.h"

namespace specula::scene {

Mesh parametricMesh(std::string name, std::vector<math::BezierPatch> patches, int segments) {
  const math::PatchGrid grid = math::tessellatePatchGrid(patches, segments);
  Mesh mesh{std::move(name), {}, grid.indices, std::move(patches), segments};
  mesh.vertices.reserve(grid.positions.size());
  for (std::size_t i = 0; i < grid.positions.size(); ++i)
    mesh.vertices.push_back({glm::vec3(grid.positions[i]), glm::vec3(grid.normals[i]), glm::vec2(grid.uvs[i])});
  return mesh;
}

}  // namespace specula::scene
