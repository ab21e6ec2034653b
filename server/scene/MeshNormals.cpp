#include "scene/MeshNormals.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace specula::scene {

namespace {

const glm::vec3 kFallbackNormal{0.0f, 1.0f, 0.0f};

// Twice the triangle's area times its unit normal: summing these weights faces by area.
glm::vec3 weightedFaceNormal(const Mesh& mesh, std::size_t triangle) {
  const glm::vec3& a = mesh.vertices[mesh.indices[3 * triangle]].position;
  const glm::vec3& b = mesh.vertices[mesh.indices[3 * triangle + 1]].position;
  const glm::vec3& c = mesh.vertices[mesh.indices[3 * triangle + 2]].position;
  return glm::cross(b - a, c - a);
}

glm::vec3 unitOrFallback(const glm::vec3& v) {
  const float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : kFallbackNormal;
}

struct PositionHash {
  std::size_t operator()(const glm::vec3& p) const {
    // Adding 0.0f turns -0.0f into +0.0f so equal positions hash alike.
    const auto bits = [](float f) { return static_cast<std::size_t>(std::bit_cast<std::uint32_t>(f + 0.0f)); };
    return (bits(p.x) * 73856093u) ^ (bits(p.y) * 19349663u) ^ (bits(p.z) * 83492791u);
  }
};

}  // namespace

void computeSmoothNormals(Mesh& mesh) {
  std::unordered_map<glm::vec3, std::size_t, PositionHash> slotOf;
  std::vector<std::size_t> slot(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    slot[i] = slotOf.emplace(mesh.vertices[i].position, slotOf.size()).first->second;
  std::vector<glm::vec3> sum(slotOf.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 n = weightedFaceNormal(mesh, t);
    for (std::size_t corner = 0; corner < 3; ++corner) sum[slot[mesh.indices[3 * t + corner]]] += n;
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i].normal = unitOrFallback(sum[slot[i]]);
}

void makeFlatShaded(Mesh& mesh) {
  std::vector<Vertex> vertices;
  vertices.reserve(mesh.indices.size());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 normal = unitOrFallback(weightedFaceNormal(mesh, t));
    for (std::size_t corner = 0; corner < 3; ++corner) {
      vertices.push_back(mesh.vertices[mesh.indices[3 * t + corner]]);
      vertices.back().normal = normal;
    }
  }
  mesh.vertices = std::move(vertices);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
}

}  // namespace specula::scene
