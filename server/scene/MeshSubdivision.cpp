#include "scene/MeshSubdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace specula::scene {

namespace {

Vertex midpointOf(const Vertex& a, const Vertex& b) {
  const glm::vec3 normal = a.normal + b.normal;
  const float length = glm::length(normal);
  return {0.5f * (a.position + b.position), length > 0.0f ? normal / length : a.normal, 0.5f * (a.uv + b.uv)};
}

// Which edges (v0 → v1, v1 → v2, v2 → v0) of triangle `t` are longer than `maxEdgeLength`.
std::array<bool, 3> longEdgesOf(const Mesh& mesh, std::size_t t, float maxEdgeLength) {
  std::array<bool, 3> longEdge{};
  for (std::size_t e = 0; e < 3; ++e)
    longEdge[e] = glm::distance(mesh.vertices[mesh.indices[3 * t + e]].position,
                                mesh.vertices[mesh.indices[3 * t + (e + 1) % 3]].position) > maxEdgeLength;
  return longEdge;
}

// The triangles the next round makes: a triangle with k long edges becomes k + 1.
std::size_t trianglesAfterRound(const Mesh& mesh, float maxEdgeLength) {
  std::size_t triangles = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::array<bool, 3> longEdge = longEdgesOf(mesh, t, maxEdgeLength);
    triangles += 1 + static_cast<std::size_t>(std::count(longEdge.begin(), longEdge.end(), true));
  }
  return triangles;
}

// Every triangle of the result has edges no longer than `maxEdgeLength`, so at most an equilateral
// one's area: the mesh's area over that is a floor on the triangles it needs.
double fewestTrianglesAfterSplitting(const Mesh& mesh, float maxEdgeLength) {
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec3 a = mesh.vertices[mesh.indices[3 * t]].position,
                     b = mesh.vertices[mesh.indices[3 * t + 1]].position,
                     c = mesh.vertices[mesh.indices[3 * t + 2]].position;
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  const double largestTriangle = std::sqrt(3.0) / 4.0 * double(maxEdgeLength) * double(maxEdgeLength);
  return area / largestTriangle;
}

// One round: every long edge split once.
void splitRound(Mesh& mesh, float maxEdgeLength) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) -> std::uint32_t {
    const auto key = std::minmax(a, b);
    const auto [entry, added] = midpoints.emplace(key, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(midpointOf(mesh.vertices[key.first], mesh.vertices[key.second]));
    return entry->second;
  };
  std::vector<std::uint32_t> indices;
  indices.reserve(mesh.indices.size());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::array<std::uint32_t, 3> v{mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
    const std::array<bool, 3> longEdge = longEdgesOf(mesh, t, maxEdgeLength);
    const auto count = std::count(longEdge.begin(), longEdge.end(), true);
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      indices.insert(indices.end(), {a, b, c});
    };
    if (count == 0) {
      emit(v[0], v[1], v[2]);
      continue;
    }
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
}

}  // namespace

std::optional<Mesh> subdivideLongEdges(const Mesh& mesh, float maxEdgeLength, std::size_t maxTriangles) {
  // Refused before any work where the area alone says so, and before any round that would pass the
  // limit, so a hostile max_edge costs neither minutes nor gigabytes.
  if (fewestTrianglesAfterSplitting(mesh, maxEdgeLength) > double(maxTriangles)) return std::nullopt;
  Mesh result = mesh;
  for (std::size_t next = trianglesAfterRound(result, maxEdgeLength); next != result.triangleCount();
       next = trianglesAfterRound(result, maxEdgeLength)) {
    if (next > maxTriangles) return std::nullopt;
    splitRound(result, maxEdgeLength);
  }
  return result;
}

}  // namespace specula::scene
