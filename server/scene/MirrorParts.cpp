#include "scene/MirrorParts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace specula::scene {

namespace {

enum class TriangleClass { Flat, Convex, Concave, Saddle };

// Normals at one welded position this close (cosine) are continuous: the surface has no crease there.
constexpr float kSmoothCosine = 0.9995f;
// A triangle whose normals turn less than this (radians, over its mean edge) is flat.
constexpr float kFlatTurn = 1e-3f;
// A principal curvature below this share of the other's magnitude counts as zero (a cylinder is
// convex, the inside of a torus-shaped rim is convex when its tube curvature dominates).
constexpr float kCurvatureTolerance = 0.1f;
// Parts smaller than this share of the mesh's area join a neighbour: thin strips where a profile
// changes curvature (a bowl's rim) or turns at a crease (its foot) are not worth a search of their own.
constexpr double kSmallPartShare = 0.05;

// Principal curvatures of the shape operator fitted to the triangle's vertex normals in least
// squares (Rusinkiewicz 2004): positive where normals diverge, i.e. convex seen from their side.
TriangleClass classify(const std::array<glm::vec3, 3>& p, const std::array<glm::vec3, 3>& n) {
  const glm::vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
  const float crossLength = glm::length(cross);
  const float meanEdge = (glm::length(p[1] - p[0]) + glm::length(p[2] - p[1]) + glm::length(p[0] - p[2])) / 3.0f;
  if (!(crossLength > 1e-12f * meanEdge * meanEdge) || !(meanEdge > 0.0f)) return TriangleClass::Flat;
  const glm::vec3 face = cross / crossLength;
  const glm::vec3 u = glm::normalize(p[1] - p[0]);
  const glm::vec3 v = glm::cross(face, u);
  // Unknowns (a, b, c) of S = [a b; b c]; each edge gives two rows: (eu, ev, 0)·x = dn·u, (0, eu, ev)·x = dn·v.
  glm::dmat3 normal(0.0);
  glm::dvec3 rhs(0.0);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const glm::vec3 e = p[j] - p[i];
    const glm::vec3 dn = glm::normalize(n[j]) - glm::normalize(n[i]);
    const glm::dvec3 rows[2] = {{glm::dot(e, u), glm::dot(e, v), 0.0}, {0.0, glm::dot(e, u), glm::dot(e, v)}};
    const double values[2] = {glm::dot(dn, u), glm::dot(dn, v)};
    for (int r = 0; r < 2; ++r) {
      normal += glm::outerProduct(rows[r], rows[r]);
      rhs += rows[r] * values[r];
    }
  }
  if (std::abs(glm::determinant(normal)) < 1e-30) return TriangleClass::Flat;
  const glm::dvec3 s = glm::inverse(normal) * rhs;
  const double mean = 0.5 * (s.x + s.z);
  const double spread = std::sqrt(0.25 * (s.x - s.z) * (s.x - s.z) + s.y * s.y);
  const double k1 = mean + spread, k2 = mean - spread;  // k1 >= k2
  if (std::max(std::abs(k1), std::abs(k2)) * meanEdge < kFlatTurn) return TriangleClass::Flat;
  if (k1 > 0.0 && k2 >= -kCurvatureTolerance * k1) return TriangleClass::Convex;
  if (k2 < 0.0 && k1 <= -kCurvatureTolerance * k2) return TriangleClass::Concave;
  return TriangleClass::Saddle;
}

SurfaceKind kindOf(TriangleClass c) {
  switch (c) {
    case TriangleClass::Concave: return SurfaceKind::Concave;
    case TriangleClass::Saddle: return SurfaceKind::Saddle;
    default: return SurfaceKind::Convex;  // a plane reflects like a convex part: one point at most
  }
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Triangle pairs sharing an edge (positions welded), and whether the surface is smooth across it.
struct Adjacency {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> smooth, creased;
};

Adjacency adjacencyOf(const Mesh& mesh) {
  // Weld on a grid of 1e-6 of the mesh's extent, so duplicated seam vertices meet.
  glm::vec3 low(1e30f), high(-1e30f);
  for (const Vertex& v : mesh.vertices) {
    low = glm::min(low, v.position);
    high = glm::max(high, v.position);
  }
  const float cell = std::max(1e-6f * glm::length(high - low), 1e-30f);
  std::map<std::array<long long, 3>, std::uint32_t> welded;
  std::vector<std::uint32_t> weldOf(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec3 q = glm::round((mesh.vertices[i].position - low) / cell);
    const std::array<long long, 3> key{static_cast<long long>(q.x), static_cast<long long>(q.y),
                                       static_cast<long long>(q.z)};
    weldOf[i] = welded.emplace(key, static_cast<std::uint32_t>(welded.size())).first->second;
  }
  // Edge (welded ends, low first) → the triangles using it, with their own vertex at each end.
  struct EdgeUse {
    std::uint32_t triangle, atLow, atHigh;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<EdgeUse>> edges;
  for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
      if (weldOf[a] == weldOf[b]) continue;
      if (weldOf[a] > weldOf[b]) std::swap(a, b);
      edges[{weldOf[a], weldOf[b]}].push_back({t, a, b});
    }
  const auto sameNormal = [&](std::uint32_t a, std::uint32_t b) {
    return glm::dot(glm::normalize(mesh.vertices[a].normal), glm::normalize(mesh.vertices[b].normal)) > kSmoothCosine;
  };
  Adjacency adjacency;
  for (const auto& [key, uses] : edges)
    for (std::size_t i = 0; i < uses.size(); ++i)
      for (std::size_t j = i + 1; j < uses.size(); ++j) {
        const bool smooth = sameNormal(uses[i].atLow, uses[j].atLow) && sameNormal(uses[i].atHigh, uses[j].atHigh);
        (smooth ? adjacency.smooth : adjacency.creased).emplace_back(uses[i].triangle, uses[j].triangle);
      }
  return adjacency;
}

}  // namespace

MirrorParts MirrorParts::of(const Mesh& mesh, MirrorCurvature curvature) {
  const std::size_t triangleCount = mesh.triangleCount();
  if (curvature != MirrorCurvature::Mixed || triangleCount == 0) {
    const SurfaceKind kind = curvature == MirrorCurvature::Concave ? SurfaceKind::Concave : SurfaceKind::Convex;
    return {{MirrorPart{kind, static_cast<std::uint32_t>(triangleCount)}}, {}};
  }

  std::vector<TriangleClass> classes(triangleCount);
  std::vector<double> area(triangleCount);
  for (std::size_t t = 0; t < triangleCount; ++t) {
    std::array<glm::vec3, 3> p, n;
    for (int k = 0; k < 3; ++k) {
      p[k] = mesh.vertices[mesh.indices[3 * t + k]].position;
      n[k] = mesh.vertices[mesh.indices[3 * t + k]].normal;
    }
    classes[t] = classify(p, n);
    area[t] = 0.5 * glm::length(glm::cross(glm::dvec3(p[1] - p[0]), glm::dvec3(p[2] - p[0])));
  }
  const Adjacency adjacency = adjacencyOf(mesh);

  // Flat triangles take the class of a smooth neighbour, spreading outwards until none is left.
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : adjacency.smooth) {
      if (classes[a] == TriangleClass::Flat && classes[b] != TriangleClass::Flat) {
        classes[a] = classes[b];
        changed = true;
      } else if (classes[b] == TriangleClass::Flat && classes[a] != TriangleClass::Flat) {
        classes[b] = classes[a];
        changed = true;
      }
    }
  }
  UnionFind components(triangleCount);
  for (const auto& [a, b] : adjacency.smooth)
    if (kindOf(classes[a]) == kindOf(classes[b])) components.unite(a, b);

  // Parts by component; then rounds of merging each small part into its largest neighbour (smooth
  // neighbours first), and the smallest part while there are too many.
  std::map<std::uint32_t, double> partArea;
  for (std::uint32_t t = 0; t < triangleCount; ++t) partArea[components.find(t)] += area[t];
  const double totalArea = std::accumulate(area.begin(), area.end(), 0.0);
  const auto largestNeighbours = [&] {
    std::map<std::uint32_t, std::uint32_t> best;
    for (const auto* pairs : {&adjacency.smooth, &adjacency.creased}) {
      std::map<std::uint32_t, std::uint32_t> found;
      for (const auto& [a, b] : *pairs) {
        const std::uint32_t pa = components.find(a), pb = components.find(b);
        if (pa == pb) continue;
        for (const auto& [part, other] : {std::pair{pa, pb}, std::pair{pb, pa}}) {
          const auto it = found.find(part);
          if (it == found.end() || partArea[other] > partArea[it->second]) found[part] = other;
        }
      }
      best.merge(found);  // keeps the smooth neighbour where there is one
    }
    return best;
  };
  const auto mergeInto = [&](std::uint32_t part, std::uint32_t into) {
    into = components.find(into);
    if (into == part) return false;
    partArea[into] += partArea[part];
    partArea.erase(part);
    components.parent[part] = into;
    return true;
  };
  const auto byArea = [&] {
    std::vector<std::uint32_t> smallestFirst;
    for (const auto& entry : partArea) smallestFirst.push_back(entry.first);
    std::sort(smallestFirst.begin(), smallestFirst.end(),
              [&](std::uint32_t a, std::uint32_t b) { return partArea[a] < partArea[b]; });
    return smallestFirst;
  };
  for (bool merged = true; merged && partArea.size() > 1;) {
    merged = false;
    const auto neighbours = largestNeighbours();
    for (const std::uint32_t part : byArea()) {
      if (!partArea.contains(part) || partArea[part] >= kSmallPartShare * totalArea || partArea.size() == 1) continue;
      if (const auto it = neighbours.find(part); it != neighbours.end()) merged |= mergeInto(part, it->second);
    }
  }
  while (partArea.size() > kMaxParts) {
    const std::uint32_t smallest = byArea().front();
    const auto neighbours = largestNeighbours();
    const auto it = neighbours.find(smallest);
    mergeInto(smallest, it != neighbours.end() ? it->second : byArea().back());
  }

  // Number the parts by their first triangle; a part's kind is that of most of its area.
  MirrorParts result;
  std::map<std::uint32_t, std::uint8_t> number;
  std::vector<std::array<double, 3>> kindArea;
  result.triangleParts.resize(triangleCount);
  for (std::uint32_t t = 0; t < triangleCount; ++t) {
    const std::uint32_t root = components.find(t);
    const auto [entry, added] = number.emplace(root, static_cast<std::uint8_t>(number.size()));
    if (added) {
      result.parts.emplace_back();
      kindArea.push_back({0.0, 0.0, 0.0});
    }
    result.triangleParts[t] = entry->second;
    ++result.parts[entry->second].triangles;
    kindArea[entry->second][static_cast<std::size_t>(kindOf(classes[t]))] += area[t];
  }
  for (std::size_t i = 0; i < result.parts.size(); ++i)
    result.parts[i].kind =
        static_cast<SurfaceKind>(std::max_element(kindArea[i].begin(), kindArea[i].end()) - kindArea[i].begin());
  if (result.parts.size() == 1) result.triangleParts.clear();
  return result;
}

}  // namespace specula::scene
