#include "math/TriangleBvh.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "math/RayBox.h"

namespace specula::math {

namespace {

constexpr std::uint32_t kLeafSize = 4;

struct Builder {
  std::span<const glm::vec3> positions;
  std::span<const std::uint32_t> indices;
  std::vector<glm::vec3> centroids;
  std::vector<std::uint32_t> order;  // triangle indices, partitioned in place
  std::vector<TriangleBvh::Node>* nodes;

  glm::vec3 corner(std::uint32_t triangle, int k) const { return positions[indices[3 * triangle + k]]; }

  // Fills node `at` with triangles order[begin, end).
  void split(std::size_t at, std::uint32_t begin, std::uint32_t end, int depth) {
    glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    glm::vec3 centroidLow = low, centroidHigh = high;
    for (std::uint32_t i = begin; i < end; ++i) {
      for (int k = 0; k < 3; ++k) {
        low = glm::min(low, corner(order[i], k));
        high = glm::max(high, corner(order[i], k));
      }
      centroidLow = glm::min(centroidLow, centroids[order[i]]);
      centroidHigh = glm::max(centroidHigh, centroids[order[i]]);
    }
    (*nodes)[at].low = low;
    (*nodes)[at].high = high;
    const glm::vec3 extent = centroidHigh - centroidLow;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (end - begin <= kLeafSize || depth + 1 >= TriangleBvh::kMaxDepth || !(extent[axis] > 0.0f)) {
      (*nodes)[at].first = begin;
      (*nodes)[at].count = end - begin;
      return;
    }
    // Median split along the widest axis of the centroids: balanced, so depth stays ~log2(n).
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    const auto children = static_cast<std::uint32_t>(nodes->size());
    nodes->resize(nodes->size() + 2);
    (*nodes)[at].first = children;
    (*nodes)[at].count = 0;
    split(children, begin, middle, depth + 1);
    split(children + 1, middle, end, depth + 1);
  }
};

}  // namespace

TriangleBvh TriangleBvh::build(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
  TriangleBvh bvh;
  const auto count = static_cast<std::uint32_t>(indices.size() / 3);
  Builder builder{positions, indices, {}, std::vector<std::uint32_t>(count), &bvh.nodes_};
  std::iota(builder.order.begin(), builder.order.end(), 0u);
  builder.centroids.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t)
    builder.centroids.push_back((builder.corner(t, 0) + builder.corner(t, 1) + builder.corner(t, 2)) / 3.0f);
  if (count == 0) return bvh;
  bvh.nodes_.resize(1);
  builder.split(0, 0, count, 0);
  bvh.triangles_.reserve(count);
  for (const std::uint32_t t : builder.order)
    bvh.triangles_.push_back({builder.corner(t, 0), t, builder.corner(t, 1), 0.0f, builder.corner(t, 2), 0.0f});
  return bvh;
}

std::optional<TriangleBvh::Hit> TriangleBvh::intersect(const glm::vec3& origin, const glm::vec3& direction,
                                                       float minDistance, float maxDistance) const {
  const glm::vec3 inverse = 1.0f / direction;
  std::optional<Hit> best;
  if (nodes_.empty()) return best;
  float tMax = maxDistance;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!rayMeetsBox(node.low, node.high, origin, inverse, minDistance, tMax)) continue;
    if (node.count == 0) {
      stack.push_back(node.first);
      stack.push_back(node.first + 1);
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      // Möller–Trumbore, as in triangle-bvh.glsl.
      const Triangle& triangle = triangles_[i];
      const glm::vec3 a = triangle.a, e1 = triangle.b - a, e2 = triangle.c - a;
      const glm::vec3 p = glm::cross(direction, e2);
      const float determinant = glm::dot(e1, p);
      if (determinant == 0.0f) continue;
      const float inverseDeterminant = 1.0f / determinant;
      const glm::vec3 s = origin - a;
      const float u = glm::dot(s, p) * inverseDeterminant;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 q = glm::cross(s, e1);
      const float v = glm::dot(direction, q) * inverseDeterminant;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(e2, q) * inverseDeterminant;
      if (t <= minDistance || t >= tMax) continue;
      tMax = t;
      best = Hit{t, triangle.index, {u, v}};
    }
  }
  return best;
}

}  // namespace specula::math
