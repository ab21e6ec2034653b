#include "scene/MeshSubdivision.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace specula::scene {

namespace {

Vertex midpointOf(const Vertex& a, const Vertex& b) {
  const glm::vec3 normal = a.normal + b.normal;
  const float length = glm::length(normal);
  return {0.5f * (a.position + b.position), length > 0.0f ? normal / length : a.normal, 0.5f * (a.uv + b.uv)};
}

// One round; false when no edge was long.
bool splitRound(Mesh& mesh, float maxEdgeLength) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) -> std::uint32_t {
    const auto key = std::minmax(a, b);
    const auto [entry, added] = midpoints.emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(midpointOf(mesh.vertices[key.first], mesh.vertices[key.second]));
    return entry->second;
  };
  std::vector<std::uint32_t> indices;
  indices.reserve(mesh.indices.size());
  bool split = false;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::array<std::uint32_t, 3> v{mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    std::array<bool, 3> longEdge{};
    int count = 0;
    for (int e = 0; e < 3; ++e) {
      longEdge[e] = glm::distance(mesh.vertices[v[e]].position, mesh.vertices[v[(e + 1) % 3]].position) > maxEdgeLength;
      count += longEdge[e] ? 1 : 0;
    }
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      indices.insert(indices.end(), {a, b, c});
    };
    if (count == 0) {
      emit(v[0], v[1], v[2]);
      continue;
    }
    split = true;
    if (count == 3) {
      const std::uint32_t m01 = midpoint(v[0], v[1]), m12 = midpoint(v[1], v[2]), m20 = midpoint(v[2], v[0]);
      emit(v[0], m01, m20);
      emit(m01, v[1], m12);
      emit(m20, m12, v[2]);
      emit(m01, m12, m20);
      continue;
    }
    // Rotate so edge 0 (v0 → v1) is split, and for two, edge 1 too (or else edge 2).
    int first = 0;
    while (!longEdge[first] || (count == 2 && !longEdge[(first + 1) % 3])) ++first;
    const std::uint32_t a = v[first], b = v[(first + 1) % 3], c = v[(first + 2) % 3];
    const std::uint32_t mab = midpoint(a, b);
    if (count == 1) {
      emit(a, mab, c);
      emit(mab, b, c);
    } else {
      const std::uint32_t mbc = midpoint(b, c);
      emit(a, mab, c);
      emit(mab, b, mbc);
      emit(mab, mbc, c);
    }
  }
  mesh.indices = std::move(indices);
  return split;
}

}  // namespace

std::optional<Mesh> subdivideLongEdges(const Mesh& mesh, float maxEdgeLength, std::size_t maxTriangles) {
  Mesh result = mesh;
  // A round at most quadruples the triangles, so memory stays within four times the limit.
  while (splitRound(result, maxEdgeLength))
    if (result.triangleCount() > maxTriangles) return std::nullopt;
  return result;
}

}  // namespace specula::scene
