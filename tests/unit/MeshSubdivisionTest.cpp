// Long edges split at load ("max_edge"): no crack, same surface, every edge short enough.
#include <gtest/gtest.h>

#include "scene/MeshTopology.h"
#include "scene/MeshSubdivision.h"
#include "scene/Primitives.h"
#include "scene/SceneLoader.h"

using namespace specula::scene;

namespace {

double area(const Mesh& mesh) {
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) total += 0.5 * glm::length(topology::windingNormal(mesh, t));
  return total;
}

float longestEdge(const Mesh& mesh) {
  float longest = 0.0f;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e)
      longest = std::max(longest, glm::distance(mesh.vertices[mesh.indices[3 * t + e]].position,
                                                mesh.vertices[mesh.indices[3 * t + (e + 1) % 3]].position));
  return longest;
}

}  // namespace

TEST(MeshSubdivision, SplitsEveryLongEdgeWithoutCracksOrChangeOfSurface) {
  for (const Mesh& mesh : {primitives::box("b", {1.6f, 0.04f, 0.9f}), primitives::torus("t", 1.0f, 0.3f, 12, 6)}) {
    const auto split = subdivideLongEdges(mesh, 0.1f, 1u << 20);
    ASSERT_TRUE(split) << mesh.name;
    EXPECT_LE(longestEdge(*split), 0.1f) << mesh.name;
    EXPECT_GT(split->triangleCount(), mesh.triangleCount()) << mesh.name;
    EXPECT_NEAR(area(*split), area(mesh), 1e-4 * area(mesh)) << mesh.name;  // planar splits keep the faces
    EXPECT_TRUE(topology::isWatertight(*split)) << mesh.name;               // conforming: no T-junction
    EXPECT_EQ(topology::trianglesFacingAgainstNormals(*split), 0u) << mesh.name;
    for (const Vertex& v : split->vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
  }
}

TEST(MeshSubdivision, ShortEdgesAreLeftAloneAndTheLimitIsKept) {
  const Mesh box = primitives::box("b", glm::vec3(1.0f));
  const auto same = subdivideLongEdges(box, 2.0f, 100);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->indices, box.indices);
  EXPECT_FALSE(subdivideLongEdges(box, 1e-4f, 100000)) << "would need ~1e9 triangles";
}

TEST(MeshSubdivision, SceneFilesAskForItPerMesh) {
  const std::string json = R"({"specula_scene": 1, "camera": {"eye": [0, 2, 5], "target": [0, 0, 0]},
    "meshes": [{"name": "floor", "primitive": {"type": "grid", "size": [4, 4], "cells": [1, 1]}, "max_edge": 0.5}],
    "materials": [{"name": "a", "color": "#ffffff"}], "objects": [{"name": "floor", "mesh": "floor", "material": "a"}]})";
  auto scene = parseScene(json, ".", "inline");
  ASSERT_TRUE(scene.ok()) << scene.error();
  EXPECT_LE(longestEdge(scene->meshes[0]), 0.5f);
  EXPECT_GE(scene->meshes[0].triangleCount(), 128u);
}

// The limit is exact: a result of N triangles passes a limit of N and is refused under N - 1, also for
// slivers of no area, which only the per-round count (not the area floor) can refuse.
TEST(MeshSubdivision, TheTriangleLimitIsExactForSolidsAndSlivers) {
  Mesh sliver;
  sliver.name = "sliver";
  sliver.vertices = {
      {{0, 0, 0}, {0, 1, 0}, {0, 0}}, {{1, 0, 0}, {0, 1, 0}, {1, 0}}, {{0.5f, 1e-9f, 0}, {0, 1, 0}, {0, 1}}};
  sliver.indices = {0, 1, 2};
  for (const Mesh& mesh : {primitives::box("b", {1.6f, 0.04f, 0.9f}), sliver}) {
    const auto split = subdivideLongEdges(mesh, 0.05f, 1u << 20);
    ASSERT_TRUE(split) << mesh.name;
    const std::size_t needed = split->triangleCount();
    EXPECT_TRUE(subdivideLongEdges(mesh, 0.05f, needed)) << mesh.name;
    EXPECT_FALSE(subdivideLongEdges(mesh, 0.05f, needed - 1)) << mesh.name;
  }
}
