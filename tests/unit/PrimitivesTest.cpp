#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "scene/MeshTopology.h"
#include "scene/Primitives.h"

using namespace specula::scene;
using specula::scene::topology::isWatertight;
using specula::scene::topology::trianglesFacingAgainstNormals;
using specula::scene::topology::windingNormal;

namespace {

void expectUnitNormals(const Mesh& mesh) {
  for (const Vertex& v : mesh.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-5f) << mesh.name;
}

void expectIndicesInRange(const Mesh& mesh) {
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size()) << mesh.name;
}

// A bowl-like open profile: flat bottom from the axis, then a wall curving up and out.
std::vector<glm::vec2> cupProfile() { return {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.55f, 0.2f}, {0.62f, 0.5f}, {0.7f, 1.0f}}; }

}  // namespace

TEST(Primitives, GridHasOneVertexPerCornerAndTwoTrianglesPerCell) {
  const Mesh mesh = primitives::grid("g", 4.0f, 2.0f, 4, 3);
  EXPECT_EQ(mesh.name, "g");
  EXPECT_EQ(mesh.vertices.size(), 5u * 4u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 4u * 3u);
  expectIndicesInRange(mesh);
}

TEST(Primitives, GridIsCentredFacesUpAndUsesPositionAsUv) {
  const Mesh mesh = primitives::grid("g", 4.0f, 2.0f, 4, 3);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const Vertex& v : mesh.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
    EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(v.uv, glm::vec2(v.position.x, v.position.z));
  }
  EXPECT_EQ(lo, glm::vec3(-2.0f, 0.0f, -1.0f));
  EXPECT_EQ(hi, glm::vec3(2.0f, 0.0f, 1.0f));
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) EXPECT_GT(windingNormal(mesh, t).y, 0.0f);
}

TEST(Primitives, UvSphereCountsIncludeSeamAndPoleVertices) {
  const Mesh mesh = primitives::uvSphere("s", 1.0f, 16, 8);
  EXPECT_EQ(mesh.vertices.size(), 17u * 9u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 16u * 7u);  // one triangle per slice in each pole stack
  expectIndicesInRange(mesh);
}

TEST(Primitives, UvSphereVerticesLieOnTheSphereWithOutwardUnitNormals) {
  const Mesh mesh = primitives::uvSphere("s", 2.5f, 24, 12);
  expectUnitNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(v.position), 2.5f, 1e-5f);
    EXPECT_NEAR(glm::distance(v.normal, v.position / 2.5f), 0.0f, 1e-5f);
    EXPECT_GE(v.uv.x, 0.0f);
    EXPECT_LE(v.uv.x, 1.0f);
    EXPECT_GE(v.uv.y, 0.0f);
    EXPECT_LE(v.uv.y, 1.0f);
  }
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 centroid =
        (mesh.vertices[mesh.indices[3 * t]].position + mesh.vertices[mesh.indices[3 * t + 1]].position +
         mesh.vertices[mesh.indices[3 * t + 2]].position) /
        3.0f;
    EXPECT_GT(glm::dot(windingNormal(mesh, t), centroid), 0.0f) << "triangle " << t;
  }
}

TEST(Primitives, UvSphereIsWatertight) { EXPECT_TRUE(isWatertight(primitives::uvSphere("s", 1.0f, 12, 6))); }

namespace {

// A sphere as modelling tools write it: a (slices + 1) × (stacks + 1) grid with a seam column, every quad two
// triangles, so each pole row holds a line of vertices at one point and half its triangles have no area.
Mesh gridSphere(int slices, int stacks, bool withHole) {
  Mesh mesh;
  for (int j = 0; j <= stacks; ++j)
    for (int i = 0; i <= slices; ++i) {
      const float phi = 3.14159265f * static_cast<float>(j) / static_cast<float>(stacks);
      const float theta = 6.2831853f * static_cast<float>(i) / static_cast<float>(slices);
      const float ring = j == 0 || j == stacks ? 0.0f : std::sin(phi);  // a pole row is one point exactly
      const glm::vec3 p(ring * std::cos(theta), std::cos(phi), -ring * std::sin(theta));
      mesh.vertices.push_back({p, p, {static_cast<float>(i) / static_cast<float>(slices), 0.0f}});
    }
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      if (withHole && j == stacks / 2 && i == 0) continue;
      const auto at = [&](int column, int row) { return static_cast<std::uint32_t>(row * (slices + 1) + column); };
      for (std::uint32_t index : {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)})
        mesh.indices.push_back(index);
    }
  return mesh;
}

}  // namespace

TEST(Primitives, AGridSphereWithZeroAreaPoleTrianglesIsClosedAndOneWithAHoleIsNot) {
  const Mesh sphere = gridSphere(16, 8, false);
  std::size_t collapsed = 0;
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t) collapsed += glm::length(windingNormal(sphere, t)) < 1e-9f;
  ASSERT_EQ(collapsed, 2u * 16u) << "the generator writes the pole quads as the tools do";
  EXPECT_EQ(trianglesFacingAgainstNormals(sphere), 0u);
  EXPECT_TRUE(isWatertight(sphere));
  EXPECT_FALSE(isWatertight(gridSphere(16, 8, true))) << "a missing quad is a hole";
}

TEST(Primitives, UvSphereLatitudeRunsFromSouthPoleToNorthPole) {
  const Mesh mesh = primitives::uvSphere("s", 1.0f, 8, 4);
  for (const Vertex& v : mesh.vertices) EXPECT_NEAR(v.position.y, -std::cos(v.uv.y * glm::pi<float>()), 1e-5f);
}

TEST(Primitives, BoxHasFourVerticesPerFaceAndSpansItsSize) {
  const Mesh mesh = primitives::box("b", {2.0f, 4.0f, 6.0f});
  EXPECT_EQ(mesh.vertices.size(), 24u);
  EXPECT_EQ(mesh.triangleCount(), 12u);
  expectUnitNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(glm::abs(v.position), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_GT(glm::dot(v.normal, v.position), 0.0f);
    EXPECT_TRUE(v.uv.x == 0.0f || v.uv.x == 1.0f);
    EXPECT_TRUE(v.uv.y == 0.0f || v.uv.y == 1.0f);
  }
}

TEST(Primitives, BoxIsWatertightWithOutwardWinding) {
  const Mesh mesh = primitives::box("b", {1.0f, 2.0f, 3.0f});
  EXPECT_TRUE(isWatertight(mesh));
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
}

TEST(Primitives, OpenCylinderIsOneBandWithABoundaryAtEachEnd) {
  const Mesh mesh = primitives::cylinder("c", 0.5f, 2.0f, 10, false);
  EXPECT_EQ(mesh.vertices.size(), 2u * 11u);
  EXPECT_EQ(mesh.triangleCount(), 20u);
  EXPECT_FALSE(isWatertight(mesh));
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(glm::vec2(v.position.x, v.position.z)), 0.5f, 1e-5f);
    EXPECT_TRUE(v.position.y == 0.0f || v.position.y == 2.0f);
    EXPECT_NEAR(v.normal.y, 0.0f, 1e-6f);
  }
}

TEST(Primitives, CappedCylinderIsWatertightWithFlatCaps) {
  const Mesh mesh = primitives::cylinder("c", 0.5f, 2.0f, 10, true);
  EXPECT_TRUE(isWatertight(mesh));
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
  EXPECT_EQ(mesh.triangleCount(), 4u * 10u);  // a fan per cap plus the two-triangle side quads
  expectUnitNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    const bool onSide = std::abs(glm::length(glm::vec2(v.position.x, v.position.z)) - 0.5f) < 1e-5f;
    const bool sideNormal = std::abs(v.normal.y) < 1e-6f;
    if (sideNormal) {
      EXPECT_TRUE(onSide);
    } else {
      EXPECT_EQ(v.normal.y, v.position.y == 0.0f ? -1.0f : 1.0f);  // caps face down at y 0, up at the top
    }
  }
}

TEST(Primitives, TorusNormalsPointAwayFromTheTubeCentre) {
  const float major = 2.0f, minor = 0.5f;
  const Mesh mesh = primitives::torus("t", major, minor, 24, 12);
  EXPECT_EQ(mesh.vertices.size(), 25u * 13u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 24u * 12u);
  expectUnitNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    const glm::vec3 tubeCentre = major * glm::normalize(glm::vec3(v.position.x, 0.0f, v.position.z));
    EXPECT_NEAR(glm::distance(v.position, tubeCentre), minor, 1e-5f);
    EXPECT_NEAR(glm::distance(v.normal, (v.position - tubeCentre) / minor), 0.0f, 1e-4f);
  }
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
  EXPECT_TRUE(isWatertight(mesh));
}

TEST(Primitives, LatheOfAProfileWalkedUpwardsFacesOutwards) {
  const std::vector<glm::vec2> profile{{1.0f, 0.0f}, {1.1f, 0.5f}, {1.0f, 1.0f}};  // bends 23°: one ring
  const Mesh mesh = primitives::lathe("l", profile, 16);
  EXPECT_EQ(mesh.vertices.size(), 3u * 17u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 2u * 16u);
  expectUnitNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    const glm::vec3 radial = glm::normalize(glm::vec3(v.position.x, 0.0f, v.position.z));
    EXPECT_GT(glm::dot(v.normal, radial), 0.0f);
  }
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
}

TEST(Primitives, LatheKeepsSharpProfileCornersAndBlendsGentleOnes) {
  const std::vector<glm::vec2> profile = cupProfile();
  const Mesh mesh = primitives::lathe("cup", profile, 8);
  // The 90° corner at the bottom edge gets two rings; the gentle bends of the wall get one each.
  EXPECT_EQ(mesh.vertices.size(), 6u * 9u);
  EXPECT_EQ(mesh.triangleCount(), 8u + 3u * 2u * 8u);
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
  for (const Vertex& v : mesh.vertices) {
    if (v.position.y == 0.0f && glm::length(glm::vec2(v.position.x, v.position.z)) < 0.4f) {
      EXPECT_EQ(v.normal, glm::vec3(0, -1, 0));
    }
  }
}

TEST(Primitives, LatheUvRunsAlongSlicesAndArcLength) {
  const std::vector<glm::vec2> profile{{1.0f, 0.0f}, {1.0f, 1.0f}, {1.0f, 3.0f}};
  const Mesh mesh = primitives::lathe("l", profile, 4);
  for (const Vertex& v : mesh.vertices) EXPECT_NEAR(v.uv.y, v.position.y / 3.0f, 1e-6f);
  EXPECT_EQ(mesh.vertices.front().uv.x, 0.0f);
  EXPECT_EQ(mesh.vertices[4].uv.x, 1.0f);
}

TEST(Primitives, LatheOfAProfileClosedOnTheAxisIsWatertight) {
  // A capsule-ish solid: from the bottom pole out, up, and back to the top pole.
  const std::vector<glm::vec2> profile{{0.0f, 0.0f}, {0.6f, 0.1f}, {0.8f, 0.5f},
                                       {0.8f, 1.5f}, {0.5f, 1.9f}, {0.0f, 2.0f}};
  const Mesh mesh = primitives::lathe("l", profile, 12);
  EXPECT_TRUE(isWatertight(mesh));
  EXPECT_EQ(trianglesFacingAgainstNormals(mesh), 0u);
}

TEST(Primitives, LatheIgnoresRepeatedProfilePoints) {
  const std::vector<glm::vec2> once{{1.0f, 0.0f}, {1.0f, 1.0f}};
  const std::vector<glm::vec2> twice{{1.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}};
  EXPECT_EQ(primitives::lathe("a", twice, 6).vertices.size(), primitives::lathe("b", once, 6).vertices.size());
}

TEST(Primitives, LatheOfAProfileWithoutLengthIsEmpty) {
  const std::vector<glm::vec2> point{{1.0f, 2.0f}, {1.0f, 2.0f}};
  const Mesh mesh = primitives::lathe("l", point, 6);
  EXPECT_TRUE(mesh.vertices.empty());
  EXPECT_TRUE(mesh.indices.empty());
}

TEST(Primitives, AppendTransformsPositionsAndNormalsAndOffsetsIndices) {
  Mesh into = primitives::box("into", glm::vec3(1.0f));
  const Mesh part = primitives::grid("part", 1.0f, 1.0f, 1, 1);
  const glm::mat4 transform = glm::translate(glm::mat4(1.0f), glm::vec3(0, 5, 0)) *
                              glm::rotate(glm::mat4(1.0f), glm::half_pi<float>(), glm::vec3(1, 0, 0)) *
                              glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 1.0f, 3.0f));
  primitives::append(into, part, transform);
  ASSERT_EQ(into.vertices.size(), 24u + 4u);
  ASSERT_EQ(into.triangleCount(), 12u + 2u);
  for (std::size_t i = 0; i < part.vertices.size(); ++i) {
    const Vertex& v = into.vertices[24 + i];
    EXPECT_NEAR(glm::distance(v.position, glm::vec3(transform * glm::vec4(part.vertices[i].position, 1.0f))), 0.0f,
                1e-5f);
    EXPECT_NEAR(glm::distance(v.normal, glm::vec3(0, 0, 1)), 0.0f, 1e-5f);  // +y turned a quarter about +x
    EXPECT_EQ(v.uv, part.vertices[i].uv);
  }
  for (std::size_t k = 36; k < into.indices.size(); ++k) EXPECT_GE(into.indices[k], 24u);
  EXPECT_EQ(trianglesFacingAgainstNormals(into), 0u);
}

TEST(Primitives, AppendWithAMirroringTransformKeepsFrontFacesOutside) {
  Mesh into;
  primitives::append(into, primitives::uvSphere("s", 1.0f, 8, 4),
                     glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 2.0f, 1.0f)));
  EXPECT_EQ(trianglesFacingAgainstNormals(into), 0u);
  EXPECT_TRUE(isWatertight(into));
}
