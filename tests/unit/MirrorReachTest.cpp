// The planner's cull tests (passes/MirrorReach): an object is left out of a mirror part only when no
// reflected ray of the part can reach it. Checked on shapes with known answers, and against brute
// force: reflected rays of a sphere sampled densely must never meet an object the test left out.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "passes/MirrorReach.h"
#include "scene/MirrorParts.h"
#include "scene/Primitives.h"

using namespace specula;

namespace {

math::Bounds cube(const glm::vec3& centre, float halfSize) {
  math::Bounds bounds;
  bounds.add(centre - glm::vec3(halfSize));
  bounds.add(centre + glm::vec3(halfSize));
  return bounds;
}

passes::MirrorReach unitBall() {
  scene::AnalyticShape sphere;
  return passes::MirrorReach::ofQuadric(sphere);
}

const glm::mat4 kIdentity(1.0f);

}  // namespace

TEST(MirrorReach, AnObjectInTheEyesShadowOfAClosedConvexMirrorCannotAppearInIt) {
  const passes::MirrorReach ball = unitBall();
  const glm::vec3 eye(0.0f, 0.0f, 5.0f);
  EXPECT_FALSE(passes::canAppearIn(ball, kIdentity, cube({0.0f, 0.0f, -3.0f}, 0.2f), eye)) << "small, straight behind";
  EXPECT_TRUE(passes::canAppearIn(ball, kIdentity, cube({0.0f, 0.0f, -3.0f}, 1.5f), eye))
      << "wider than the shadow there";
  EXPECT_TRUE(passes::canAppearIn(ball, kIdentity, cube({2.5f, 0.0f, -3.0f}, 0.2f), eye)) << "beside the shadow";
  EXPECT_TRUE(passes::canAppearIn(ball, kIdentity, cube({0.0f, 0.0f, 2.5f}, 0.2f), eye))
      << "between the eye and the mirror";
  EXPECT_TRUE(passes::canAppearIn(ball, kIdentity, cube({0.0f, 0.0f, -0.5f}, 0.2f), glm::vec3(0.0f)))
      << "the eye inside the mirror";
  // Moved and scaled with the mirror: a ball of radius 2 at x = 10 shadows more.
  const glm::mat4 placed = glm::scale(glm::translate(kIdentity, {10.0f, 0.0f, 0.0f}), glm::vec3(2.0f));
  EXPECT_FALSE(passes::canAppearIn(ball, placed, cube({10.0f, 0.0f, -4.0f}, 0.6f), eye + glm::vec3(10.0f, 0.0f, 0.0f)));
  EXPECT_TRUE(passes::canAppearIn(ball, kIdentity, math::Bounds{}, eye)) << "nothing to judge: kept";
}

TEST(MirrorReach, AClosedConvexMeshGetsABallInsideItAndAnOpenOneNone) {
  const scene::Mesh sphere = scene::primitives::uvSphere("sphere", 1.0f, 64, 32);
  const scene::MirrorParts parts = scene::MirrorParts::of(sphere, scene::MirrorCurvature::Convex);
  const passes::MirrorReach closed = passes::MirrorReach::ofMeshPart(sphere, parts, 0, true);
  ASSERT_TRUE(closed.inscribed);
  EXPECT_LT(glm::length(closed.inscribed->centre), 1e-4f);
  EXPECT_LE(closed.inscribed->radius, 1.0f);
  EXPECT_GT(closed.inscribed->radius, 0.99f);
  EXPECT_LE(closed.normalCosine, -0.99f) << "a sphere's normals point every way";
  EXPECT_FALSE(passes::MirrorReach::ofMeshPart(sphere, parts, 0, false).inscribed);
}

TEST(MirrorReach, AnObjectBehindEveryTangentPlaneOfAPartCannotAppearInIt) {
  const scene::Mesh plate = scene::primitives::grid("plate", 2.0f, 2.0f, 4, 4);  // y = 0, normals +y
  const scene::MirrorParts parts = scene::MirrorParts::of(plate, scene::MirrorCurvature::Convex);
  const passes::MirrorReach reach = passes::MirrorReach::ofMeshPart(plate, parts, 0, false);
  EXPECT_NEAR(reach.normalCosine, 1.0f, 1e-6f);
  const glm::vec3 eye(0.5f, 3.0f, 2.0f);
  EXPECT_FALSE(passes::canAppearIn(reach, kIdentity, cube({0.0f, -2.0f, 0.0f}, 0.3f), eye)) << "below the plate";
  EXPECT_FALSE(passes::canAppearIn(reach, kIdentity, cube({0.0f, -0.6f, 0.0f}, 0.3f), eye))
      << "just below: a flat part's tangent planes are one plane";
  EXPECT_TRUE(passes::canAppearIn(reach, kIdentity, cube({0.0f, -0.1f, 0.0f}, 0.3f), eye))
      << "reaching above the plane";
  EXPECT_TRUE(passes::canAppearIn(reach, kIdentity, cube({3.0f, 1.0f, 0.0f}, 0.3f), eye)) << "above it";
  EXPECT_TRUE(passes::facesEye(reach, kIdentity, eye));
  EXPECT_FALSE(passes::facesEye(reach, kIdentity, {0.5f, -3.0f, 2.0f})) << "the eye below sees its back";
  // Turned upside down with the mirror: now the object below is in front of it.
  const glm::mat4 flipped = glm::rotate(kIdentity, glm::radians(180.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_TRUE(passes::canAppearIn(reach, flipped, cube({0.0f, -2.0f, 0.0f}, 0.3f), eye));
  // A transform that bends angles (stretched along one axis) skips the cone bound: kept.
  const glm::mat4 stretched = glm::scale(kIdentity, {1.0f, 1.0f, 3.0f});
  EXPECT_TRUE(passes::canAppearIn(reach, stretched, cube({0.0f, -2.0f, 0.0f}, 0.3f), eye));
}

// Brute force on a curved part: a cap of the unit sphere whose normals lie within about 35° of +y.
// Every object left out must lie behind the tangent plane at every sampled point of the cap.
TEST(MirrorReach, AnObjectLeftOutOfACurvedPartIsBehindEveryTangentPlane) {
  scene::Mesh cap = scene::primitives::grid("cap", 1.0f, 1.0f, 8, 8);
  for (scene::Vertex& vertex : cap.vertices) {
    vertex.position = glm::normalize(glm::vec3(vertex.position.x, 1.0f, vertex.position.z));
    vertex.normal = vertex.position;
  }
  const scene::MirrorParts parts = scene::MirrorParts::of(cap, scene::MirrorCurvature::Convex);
  ASSERT_EQ(parts.parts.size(), 1u);
  const passes::MirrorReach reach = passes::MirrorReach::ofMeshPart(cap, parts, 0, false);
  ASSERT_GT(reach.normalCosine, 0.75f);
  std::mt19937 random(20261203);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const glm::mat4 placed =
      glm::rotate(glm::translate(kIdentity, {1.0f, 2.0f, -0.5f}), 0.7f, glm::normalize(glm::vec3(1, 2, 3))) *
      glm::scale(kIdentity, glm::vec3(1.5f));
  int leftOut = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const glm::vec3 centre =
        glm::vec3(placed * glm::vec4(3.0f * unit(random), 2.0f * unit(random), 3.0f * unit(random), 1.0f));
    const math::Bounds object = cube(centre, 0.05f + 0.3f * (unit(random) + 1.0f));
    if (passes::canAppearIn(reach, placed, object, {0.0f, 10.0f, 0.0f})) continue;
    ++leftOut;
    const glm::mat3 normals = glm::transpose(glm::inverse(glm::mat3(placed)));
    for (const scene::Vertex& vertex : cap.vertices) {
      const glm::vec3 point(placed * glm::vec4(vertex.position, 1.0f));
      const glm::vec3 normal = glm::normalize(normals * vertex.normal);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? object.high.x : object.low.x, (corner & 2) ? object.high.y : object.low.y,
                          (corner & 4) ? object.high.z : object.low.z);
        ASSERT_LE(glm::dot(p - point, normal), 1e-4f) << "trial " << trial << ": a corner in front of the cap";
      }
    }
  }
  EXPECT_GT(leftOut, 100) << "the test must leave some out to prove anything";
}

// Brute force: for random eyes and small objects, every object the test leaves out of a unit
// sphere must be missed by all reflected rays from a dense sampling of the sphere's visible half.
TEST(MirrorReach, NoReflectedRayOfASphereMeetsAnObjectItLeftOut) {
  const passes::MirrorReach ball = unitBall();
  std::mt19937 random(20261203);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const auto direction = [&] {
    glm::vec3 d;
    do d = {unit(random), unit(random), unit(random)};
    while (glm::length(d) < 0.1f || glm::length(d) > 1.0f);
    return glm::normalize(d);
  };
  int leftOut = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const glm::vec3 eye = direction() * (1.2f + 8.0f * (unit(random) + 1.0f));
    // Objects behind the sphere, near the eye's axis through it, so many fall in the shadow.
    const glm::vec3 axis = -glm::normalize(eye);
    const glm::vec3 centre = axis * (1.5f + 4.0f * (unit(random) + 1.0f)) + 0.4f * direction() * (unit(random) + 1.0f);
    const math::Bounds object = cube(centre, 0.05f + 0.1f * (unit(random) + 1.0f));
    if (passes::canAppearIn(ball, kIdentity, object, eye)) continue;
    ++leftOut;
    const glm::vec3 objectCentre = object.center();
    const float objectRadius = object.radius();
    for (int sample = 0; sample < 4000; ++sample) {
      const glm::vec3 normal = direction();
      const glm::vec3 incoming = glm::normalize(normal - eye);  // the point on the sphere is its normal
      if (glm::dot(incoming, normal) >= 0.0f) continue;         // seen from behind
      const glm::vec3 reflected = glm::reflect(incoming, normal);
      const glm::vec3 toObject = objectCentre - normal;
      const float along = glm::dot(toObject, reflected);
      const float miss = glm::length(toObject - std::max(along, 0.0f) * reflected);
      ASSERT_GT(miss, objectRadius) << "trial " << trial << ": a reflected ray meets an object that was left out";
    }
  }
  EXPECT_GT(leftOut, 20) << "too few objects in the shadow to check the bound";
}

TEST(MirrorReach, TheLargestRadiusOfCurvatureIsTheSpheresTheEllipsoidsFlattestAndInfiniteOnAFlatPart) {
  const scene::Mesh sphere = scene::primitives::uvSphere("sphere", 2.0f, 64, 32);
  const scene::MirrorParts sphereParts = scene::MirrorParts::of(sphere, scene::MirrorCurvature::Convex);
  EXPECT_NEAR(passes::MirrorReach::ofMeshPart(sphere, sphereParts, 0, true).largestCurvatureRadius, 2.0f, 0.02f);
  const scene::Mesh box = scene::primitives::box("box", glm::vec3(1.0f));
  const scene::MirrorParts boxParts = scene::MirrorParts::of(box, scene::MirrorCurvature::Mixed);
  EXPECT_TRUE(std::isinf(passes::MirrorReach::ofMeshPart(box, boxParts, 0, false).largestCurvatureRadius));
  scene::AnalyticShape ellipsoid;
  ellipsoid.radii = {3.0f, 2.0f, 1.0f};
  const passes::MirrorReach exact = passes::MirrorReach::ofQuadric(ellipsoid);
  EXPECT_FLOAT_EQ(exact.largestCurvatureRadius, 9.0f);
  EXPECT_FLOAT_EQ(passes::worldCurvatureRadius(exact, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))), 18.0f);
  EXPECT_TRUE(std::isinf(passes::worldCurvatureRadius(exact, glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 1.0f)))))
      << "a stretch changes curvature unevenly";
}
