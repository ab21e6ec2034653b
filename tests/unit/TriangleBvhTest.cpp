// The mirror-mesh hierarchy its reflected rays are cast against, checked against brute force.
#include <gtest/gtest.h>

#include <random>

#include "math/TriangleBvh.h"
#include "scene/Primitives.h"

using specula::math::TriangleBvh;

namespace {

std::vector<glm::vec3> positionsOf(const specula::scene::Mesh& mesh) {
  std::vector<glm::vec3> positions;
  for (const auto& v : mesh.vertices) positions.push_back(v.position);
  return positions;
}

// Every triangle tested: the answer the hierarchy must reproduce.
std::optional<float> bruteForce(const TriangleBvh& bvh, const glm::vec3& origin, const glm::vec3& direction) {
  std::optional<float> best;
  for (const TriangleBvh::Triangle& triangle : bvh.triangles()) {
    TriangleBvh single = TriangleBvh::build(std::vector<glm::vec3>{triangle.a, triangle.b, triangle.c},
                                            std::vector<std::uint32_t>{0, 1, 2});
    if (auto hit = single.intersect(origin, direction, 1e-6f, 1e30f); hit && (!best || hit->distance < *best))
      best = hit->distance;
  }
  return best;
}

}  // namespace

TEST(TriangleBvh, NearestHitsMatchBruteForceOnATorus) {
  const auto torus = specula::scene::primitives::torus("t", 1.0f, 0.3f, 48, 24);
  const auto positions = positionsOf(torus);
  const TriangleBvh bvh = TriangleBvh::build(positions, torus.indices);
  ASSERT_EQ(bvh.triangles().size(), torus.triangleCount());
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::vec3 origin(2.0f * uniform(random), 0.5f * uniform(random), 2.0f * uniform(random));
    const glm::vec3 direction = glm::normalize(glm::vec3(uniform(random), uniform(random), uniform(random)) + 1e-3f);
    const auto hit = bvh.intersect(origin, direction, 1e-6f, 1e30f);
    const auto expected = bruteForce(bvh, origin, direction);
    ASSERT_EQ(hit.has_value(), expected.has_value()) << "ray " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(hit->distance, *expected, 1e-5f) << "ray " << i;
    // The reported triangle and barycentrics give back the hit point.
    const glm::vec3 a = positions[torus.indices[3 * hit->triangle]],
                    b = positions[torus.indices[3 * hit->triangle + 1]],
                    c = positions[torus.indices[3 * hit->triangle + 2]];
    const glm::vec3 point = a + hit->barycentric.x * (b - a) + hit->barycentric.y * (c - a);
    EXPECT_LT(glm::distance(point, origin + hit->distance * direction), 1e-4f) << "ray " << i;
  }
  EXPECT_GT(hits, 50);
}

TEST(TriangleBvh, DistanceLimitsAreExclusive) {
  const auto grid = specula::scene::primitives::grid("g", 2.0f, 2.0f, 4, 4);
  const TriangleBvh bvh = TriangleBvh::build(positionsOf(grid), grid.indices);
  const glm::vec3 origin(0.1f, 1.0f, 0.2f), down(0.0f, -1.0f, 0.0f);
  ASSERT_TRUE(bvh.intersect(origin, down, 0.0f, 2.0f));
  EXPECT_FLOAT_EQ(bvh.intersect(origin, down, 0.0f, 2.0f)->distance, 1.0f);
  EXPECT_FALSE(bvh.intersect(origin, down, 0.0f, 0.99f));
  EXPECT_FALSE(bvh.intersect(origin, down, 1.01f, 2.0f));
  EXPECT_FALSE(bvh.intersect(origin, -down, 0.0f, 10.0f));
}

TEST(TriangleBvh, StaysWithinTheTraversalStackAndKeepsDegenerateInput) {
  // A long strip of slivers: balanced splits keep the depth logarithmic.
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  for (std::uint32_t i = 0; i < 20000; ++i) {
    positions.insert(positions.end(),
                     {glm::vec3(float(i), 0, 0), glm::vec3(float(i) + 1, 0, 0), glm::vec3(float(i), 1e-7f, 0)});
    indices.insert(indices.end(), {3 * i, 3 * i + 1, 3 * i + 2});
  }
  const TriangleBvh bvh = TriangleBvh::build(positions, indices);
  EXPECT_EQ(bvh.triangles().size(), 20000u);
  std::vector<std::pair<std::uint32_t, int>> stack{{0, 1}};
  int deepest = 0;
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    if (bvh.nodes()[node].count == 0) {
      stack.push_back({bvh.nodes()[node].first, depth + 1});
      stack.push_back({bvh.nodes()[node].first + 1, depth + 1});
    }
  }
  EXPECT_LT(deepest, TriangleBvh::kMaxDepth);
  EXPECT_FALSE(TriangleBvh::build({}, {}).intersect(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), 0.0f, 1e30f));
}
