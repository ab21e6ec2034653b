// Mirror meshes split into parts of one curvature each: the search runs once per part.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/MirrorParts.h"
#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"

using namespace specula::scene;

namespace {

glm::vec3 triangleCentre(const Mesh& mesh, std::size_t t) {
  return (mesh.vertices[mesh.indices[3 * t]].position + mesh.vertices[mesh.indices[3 * t + 1]].position +
          mesh.vertices[mesh.indices[3 * t + 2]].position) /
         3.0f;
}

}  // namespace

TEST(MirrorParts, SmoothSphereIsOneConvexPart) {
  const MirrorParts parts = MirrorParts::of(primitives::uvSphere("s", 1.0f, 64, 32), MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 1u);
  EXPECT_EQ(parts.parts[0].kind, SurfaceKind::Convex);
  EXPECT_TRUE(parts.triangleParts.empty());
  EXPECT_TRUE(parts.cannotSeeItself(true));
  EXPECT_FALSE(parts.cannotSeeItself(false));
}

TEST(MirrorParts, InsideOutSphereIsOneConcavePart) {
  Mesh sphere = primitives::uvSphere("s", 1.0f, 48, 24);
  for (Vertex& v : sphere.vertices) v.normal = -v.normal;
  const MirrorParts parts = MirrorParts::of(sphere, MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 1u);
  EXPECT_EQ(parts.parts[0].kind, SurfaceKind::Concave);
  EXPECT_FALSE(parts.cannotSeeItself(true));
}

TEST(MirrorParts, TorusSplitsIntoItsConvexOutsideAndSaddleInside) {
  const Mesh torus = primitives::torus("t", 1.0f, 0.3f, 64, 32);
  const MirrorParts parts = MirrorParts::of(torus, MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 2u);
  ASSERT_EQ(parts.triangleParts.size(), torus.triangleCount());
  for (std::size_t t = 0; t < torus.triangleCount(); ++t) {
    const glm::vec3 c = triangleCentre(torus, t);
    const float radial = glm::length(glm::vec2(c.x, c.z));
    const SurfaceKind kind = parts.parts[parts.triangleParts[t]].kind;
    if (radial > 1.05f) {
      EXPECT_EQ(kind, SurfaceKind::Convex) << "outer ring, triangle " << t;
    } else if (radial < 0.8f) {
      EXPECT_EQ(kind, SurfaceKind::Saddle) << "inner ring, triangle " << t;
    }
  }
}

TEST(MirrorParts, KitchenBowlSplitsIntoConvexOutsideAndConcaveInside) {
  const Scene kitchen = builtin::kitchenScene();
  const auto bowl =
      std::find_if(kitchen.objects.begin(), kitchen.objects.end(), [](const auto& o) { return o.name == "bowl"; });
  ASSERT_NE(bowl, kitchen.objects.end());
  const Mesh& mesh = kitchen.meshes[bowl->mesh];
  const MirrorParts parts = MirrorParts::of(mesh, bowl->mirror->curvature);
  // Outer wall with rim and foot, inner wall.
  ASSERT_EQ(parts.parts.size(), 2u);
  std::set<std::uint8_t> inside, outside;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    // Inner wall normals point up and in, outer wall normals down and out; the band next to the
    // rim (y > 0.09), where the rim's normals blend into the wall's, may go either way.
    const Vertex& v = mesh.vertices[mesh.indices[3 * t]];
    const float outwards = glm::dot(glm::vec2(v.normal.x, v.normal.z), glm::vec2(v.position.x, v.position.z));
    const std::uint8_t part = parts.triangleParts[t];
    if (outwards < -1e-3f && v.normal.y > 0.2f && v.position.y < 0.09f) {
      EXPECT_EQ(parts.parts[part].kind, SurfaceKind::Concave) << "inside, triangle " << t;
      inside.insert(part);
    } else if (outwards > 1e-3f && v.normal.y < -0.2f) {
      EXPECT_EQ(parts.parts[part].kind, SurfaceKind::Convex) << "outside, triangle " << t;
      outside.insert(part);
    }
  }
  EXPECT_EQ(inside.size(), 1u);
  EXPECT_EQ(outside.size(), 1u);
}

TEST(MirrorParts, CreasesSeparateTheFacesOfABox) {
  const MirrorParts parts = MirrorParts::of(primitives::box("b", glm::vec3(1.0f)), MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 6u);
  for (const MirrorPart& part : parts.parts) {
    EXPECT_EQ(part.kind, SurfaceKind::Convex);
    EXPECT_EQ(part.triangles, 2u);
  }
}

TEST(MirrorParts, FlatGridIsOnePart) {
  const MirrorParts parts = MirrorParts::of(primitives::grid("g", 2.0f, 2.0f, 8, 8), MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 1u);
  EXPECT_EQ(parts.parts[0].kind, SurfaceKind::Convex);
}

TEST(MirrorParts, DeclaredCurvatureKeepsTheMeshWhole) {
  const Mesh torus = primitives::torus("t", 1.0f, 0.3f, 32, 16);
  const MirrorParts convex = MirrorParts::of(torus, MirrorCurvature::Convex);
  ASSERT_EQ(convex.parts.size(), 1u);
  EXPECT_EQ(convex.parts[0].kind, SurfaceKind::Convex);
  EXPECT_EQ(convex.parts[0].triangles, torus.triangleCount());
  const MirrorParts concave = MirrorParts::of(torus, MirrorCurvature::Concave);
  ASSERT_EQ(concave.parts.size(), 1u);
  EXPECT_EQ(concave.parts[0].kind, SurfaceKind::Concave);
}

TEST(MirrorParts, ManyPiecesMergeDownToTheLimit) {
  Mesh many{"many", {}, {}};
  for (int i = 0; i < 20; ++i)
    primitives::append(many, primitives::box("b", glm::vec3(0.1f)),
                       glm::translate(glm::mat4(1.0f), glm::vec3(float(i), 0.0f, 0.0f)));
  const MirrorParts parts = MirrorParts::of(many, MirrorCurvature::Mixed);
  ASSERT_LE(parts.parts.size(), MirrorParts::kMaxParts);
  ASSERT_EQ(parts.triangleParts.size(), many.triangleCount());
  std::uint32_t total = 0;
  for (const MirrorPart& part : parts.parts) total += part.triangles;
  EXPECT_EQ(total, many.triangleCount());
  for (const std::uint8_t part : parts.triangleParts) EXPECT_LT(part, parts.parts.size());
}

TEST(MirrorParts, DegenerateMeshesGiveOnePart) {
  EXPECT_EQ(MirrorParts::of(Mesh{"empty", {}, {}}, MirrorCurvature::Mixed).parts.size(), 1u);
  Mesh sliver{
      "sliver", {{{0, 0, 0}, {0, 1, 0}, {}}, {{1, 0, 0}, {0, 1, 0}, {}}, {{2, 0, 0}, {0, 1, 0}, {}}}, {0, 1, 2}};
  const MirrorParts parts = MirrorParts::of(sliver, MirrorCurvature::Mixed);
  ASSERT_EQ(parts.parts.size(), 1u);
  EXPECT_EQ(parts.parts[0].triangles, 1u);
}
