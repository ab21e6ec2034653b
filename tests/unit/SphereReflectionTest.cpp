#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "math/Reflection.h"
#include "math/SphereReflection.h"

using namespace specula::math;

namespace {

// The solution satisfies the law of reflection, lies on the sphere and in the eye–centre–vertex plane.
void expectExactReflection(const Sphere& s, const glm::dvec3& eye, const glm::dvec3& vertex, const glm::dvec3& r,
                           double tolerance = 1e-10) {
  ASSERT_TRUE(std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z));
  const glm::dvec3 n = glm::normalize(r - s.center);
  EXPECT_NEAR(glm::length(r - s.center), s.radius, 1e-12 * s.radius);
  EXPECT_LT(reflectionError(r, n, eye, vertex), tolerance);
  EXPECT_GE(glm::dot(n, eye - r), -1e-12) << "R must face the eye";
  EXPECT_GE(glm::dot(n, vertex - r), -1e-12) << "R must face the vertex";
  const glm::dvec3 planeNormal = glm::cross(eye - s.center, vertex - s.center);
  if (glm::length(planeNormal) > 1e-9) {
    EXPECT_NEAR(glm::dot(glm::normalize(planeNormal), r - s.center), 0.0, 1e-9 * s.radius);
  }
}

}  // namespace

TEST(SphereReflection, GenericConfigurationSatisfiesTheLawOfReflection) {
  const Sphere s{{0.3, -0.2, 1.0}, 1.5};
  const glm::dvec3 eye(4.0, 3.0, 6.0), vertex(-3.0, -1.0, 2.5);
  auto r = sphereReflectionPoint(s, eye, vertex);
  ASSERT_TRUE(r);
  expectExactReflection(s, eye, vertex, *r);
}

TEST(SphereReflection, SymmetricEyeAndVertexReflectHalfwayBetweenThem) {
  const Sphere s{{0.0, 0.0, 0.0}, 1.0};
  auto r = sphereReflectionPoint(s, {3.0, 2.0, 0.0}, {-3.0, 2.0, 0.0});
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 0.0, 1e-14);
  EXPECT_NEAR(r->y, 1.0, 1e-14);
}

TEST(SphereReflection, CollinearVertexInFrontReflectsAtThePointFacingTheEye) {
  const Sphere s{{1.0, 1.0, 1.0}, 2.0};
  auto r = sphereReflectionPoint(s, {1.0, 1.0, 11.0}, {1.0, 1.0, 5.0});
  ASSERT_TRUE(r);
  EXPECT_NEAR(glm::length(*r - glm::dvec3(1.0, 1.0, 3.0)), 0.0, 1e-14);
}

TEST(SphereReflection, NearlyCollinearConfigurationsStayFiniteAndExact) {
  const Sphere s{{0.0, 0.0, 0.0}, 1.0};
  for (double offset : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15}) {
    const glm::dvec3 eye(0.0, 0.0, 5.0), vertex(offset, 0.0, 2.0);
    auto r = sphereReflectionPoint(s, eye, vertex);
    ASSERT_TRUE(r) << offset;
    expectExactReflection(s, eye, vertex, *r, 1e-9);
  }
}

TEST(SphereReflection, GrazingEyeAndVertexNearTheHorizonStayExact) {
  const Sphere s{{0.0, 0.0, 0.0}, 1.0};
  // Eye and vertex both nearly tangent to the sphere, on either side of the point (0, 1, 0).
  const glm::dvec3 eye(10.0, 1.0 + 1e-6, 0.0), vertex(-10.0, 1.0 + 1e-6, 0.0);
  auto r = sphereReflectionPoint(s, eye, vertex);
  ASSERT_TRUE(r);
  expectExactReflection(s, eye, vertex, *r, 1e-9);
}

TEST(SphereReflection, VertexHiddenBehindTheSphereHasNoVisibleReflection) {
  const Sphere s{{0.0, 0.0, 0.0}, 1.0};
  EXPECT_FALSE(sphereReflectionPoint(s, {0.0, 0.0, 5.0}, {0.0, 0.0, -5.0}));
  EXPECT_FALSE(sphereReflectionPoint(s, {0.0, 0.0, 5.0}, {0.01, 0.0, -1.05}));
}

TEST(SphereReflection, EyeOrVertexInsideTheSphereIsRefused) {
  const Sphere s{{0.0, 0.0, 0.0}, 1.0};
  EXPECT_FALSE(sphereReflectionPoint(s, {0.0, 0.0, 0.5}, {3.0, 0.0, 0.0}));
  EXPECT_FALSE(sphereReflectionPoint(s, {0.0, 0.0, 5.0}, {0.0, 0.9, 0.0}));
  EXPECT_FALSE(sphereReflectionPoint(s, {0.0, 0.0, 5.0}, {std::nan(""), 0.0, 2.0}));
}

TEST(SphereReflection, FarEyeAndTranslatedSceneKeepFullPrecision) {
  const Sphere s{{1e4, -2e3, 5e3}, 1.0};
  const glm::dvec3 eye = s.center + glm::dvec3(0.0, 1e4, 1e4), vertex = s.center + glm::dvec3(2.0, 0.5, 0.0);
  auto r = sphereReflectionPoint(s, eye, vertex);
  ASSERT_TRUE(r);
  expectExactReflection(s, eye, vertex, *r, 1e-9);
}

TEST(SphereReflection, RandomConfigurationsAreExactOrReportedHidden) {
  std::mt19937_64 random(20261122);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), distance(1.0001, 30.0);
  auto direction = [&] {
    glm::dvec3 d;
    do d = {unit(random), unit(random), unit(random)};
    while (glm::length(d) < 0.1 || glm::length(d) > 1.0);
    return glm::normalize(d);
  };
  int solved = 0;
  for (int i = 0; i < 20000; ++i) {
    const Sphere s{{unit(random), unit(random), unit(random)}, 0.5 + std::abs(unit(random))};
    const glm::dvec3 eye = s.center + s.radius * distance(random) * direction();
    const glm::dvec3 vertex = s.center + s.radius * distance(random) * direction();
    auto r = sphereReflectionPoint(s, eye, vertex);
    if (!r) continue;
    ++solved;
    const glm::dvec3 n = glm::normalize(*r - s.center);
    ASSERT_LT(reflectionError(*r, n, eye, vertex), 1e-9) << "configuration " << i;
  }
  EXPECT_GT(solved, 10000);  // most random pairs see each other in the mirror
}

TEST(Reflection, MirrorAcrossPlaneKeepsTheDistanceToThePlanePoint) {
  const glm::dvec3 r(0.0, 1.0, 0.0), n(0.0, 1.0, 0.0), v(2.0, 3.0, -1.0);
  const glm::dvec3 mirrored = mirrorAcrossPlane(r, n, v);
  EXPECT_NEAR(glm::length(mirrored - r), glm::length(v - r), 1e-14);
  EXPECT_NEAR(mirrored.y, -1.0, 1e-14);
}

TEST(Reflection, VirtualVertexOnTheEyeRayEqualsTheMirroredVertexAtAnExactReflectionPoint) {
  const Sphere s{{0.2, -0.1, 0.4}, 1.3};
  const glm::dvec3 eye(3.0, 2.5, 6.0);
  for (const glm::dvec3& vertex :
       {glm::dvec3(-2.0, 0.5, 3.0), glm::dvec3(4.0, -1.0, -2.5), glm::dvec3(0.5, 3.0, 0.0)}) {
    auto r = sphereReflectionPoint(s, eye, vertex);
    ASSERT_TRUE(r);
    const glm::dvec3 n = glm::normalize(*r - s.center);
    EXPECT_LT(glm::length(virtualVertex(eye, *r, vertex) - mirrorAcrossPlane(*r, n, vertex)), 1e-9);
  }
}
