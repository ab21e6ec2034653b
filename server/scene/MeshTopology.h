#pragma once
// Geometry checks: watertightness and winding (the glTF importer decides a mirror is closed by the
// first; the primitive and built-in scene tests use both).
#include <cmath>
#include <glm/glm.hpp>
#include <map>
#include <tuple>
#include <utility>

#include "scene/Mesh.h"

namespace specula::scene::topology {

// Area-weighted normal of triangle t from its winding (counter-clockwise = front).
inline glm::vec3 windingNormal(const Mesh& mesh, std::size_t t) {
  const glm::vec3& a = mesh.vertices[mesh.indices[3 * t]].position;
  const glm::vec3& b = mesh.vertices[mesh.indices[3 * t + 1]].position;
  const glm::vec3& c = mesh.vertices[mesh.indices[3 * t + 2]].position;
  return glm::cross(b - a, c - a);
}

// Counts triangles whose winding faces away from their own vertex normals; zero for a consistent mesh.
inline std::size_t trianglesFacingAgainstNormals(const Mesh& mesh) {
  std::size_t against = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 shading = mesh.vertices[mesh.indices[3 * t]].normal +
                              mesh.vertices[mesh.indices[3 * t + 1]].normal +
                              mesh.vertices[mesh.indices[3 * t + 2]].normal;
    const glm::vec3 winding = windingNormal(mesh, t);
    // A triangle of no area (a parametric grid's quad at a pole) faces nowhere, so it cannot disagree.
    if (glm::length(winding) < 1e-9f) continue;
    against += glm::dot(winding, shading) <= 0.0f;
  }
  return against;
}

// True when, after merging vertices at the same position (seams, poles, creases), every directed edge
// occurs exactly once and its reverse occurs too: a closed, consistently oriented surface. Triangles
// that merging collapses (a UV sphere's quads at its poles, written as two triangles) bound nothing and
// are left out, or the common way of writing a sphere would look open.
inline bool isWatertight(const Mesh& mesh) {
  using Key = std::tuple<long, long, long>;
  std::map<Key, std::size_t> ids;
  auto id = [&](std::uint32_t index) {
    const glm::vec3& p = mesh.vertices[index].position;
    const Key key{std::lround(p.x * 1e5f), std::lround(p.y * 1e5f), std::lround(p.z * 1e5f)};
    return ids.emplace(key, ids.size()).first->second;
  };
  std::map<std::pair<std::size_t, std::size_t>, int> edges;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::size_t corner[3] = {id(mesh.indices[3 * t]), id(mesh.indices[3 * t + 1]), id(mesh.indices[3 * t + 2])};
    if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
    for (int k = 0; k < 3; ++k) ++edges[{corner[k], corner[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return !edges.empty();
}

}  // namespace specula::scene::topology
