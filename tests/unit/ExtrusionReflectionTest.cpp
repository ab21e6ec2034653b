#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "math/ExtrusionReflection.h"
#include "math/Reflection.h"
#include "math/SphereReflection.h"

using namespace specula::math;

namespace {

// The normal of the elliptic cylinder at a world point, from its implicit equation's gradient.
glm::dvec3 implicitNormal(const Extrusion& e, const glm::dvec3& point) {
  const glm::dvec3 offset = point - e.axisPoint;
  const double x = glm::dot(offset, e.u), y = glm::dot(offset, e.v);
  return glm::normalize(x / (e.radii.x * e.radii.x) * e.u + y / (e.radii.y * e.radii.y) * e.v);
}

double implicitValue(const Extrusion& e, const glm::dvec3& point) {
  const glm::dvec3 offset = point - e.axisPoint;
  const double x = glm::dot(offset, e.u) / e.radii.x, y = glm::dot(offset, e.v) / e.radii.y;
  return x * x + y * y - 1.0;
}

// The law of reflection checked independently of the solver: R on the surface, the surface's own
// normal there bisecting eye and vertex, both in front, and the eye's ray reflected at R passing the vertex.
void expectExactReflection(const Extrusion& e, const glm::dvec3& eye, const glm::dvec3& vertex, const SurfacePoint& r,
                           double tolerance = 1e-10) {
  ASSERT_TRUE(std::isfinite(r.position.x) && std::isfinite(r.position.y) && std::isfinite(r.position.z));
  EXPECT_NEAR(implicitValue(e, r.position), 0.0, 1e-12);
  const glm::dvec3 n = implicitNormal(e, r.position);
  EXPECT_NEAR(glm::length(n - r.normal), 0.0, 1e-9);
  EXPECT_LT(reflectionError(r.position, n, eye, vertex), tolerance);
  EXPECT_GE(glm::dot(n, eye - r.position), -1e-12) << "R must face the eye";
  EXPECT_GE(glm::dot(n, vertex - r.position), -1e-12) << "R must face the vertex";
  const glm::dvec3 reflected = glm::reflect(glm::normalize(r.position - eye), n);
  const glm::dvec3 toVertex = vertex - r.position;
  EXPECT_GT(glm::dot(reflected, toVertex), 0.0);
  EXPECT_LT(glm::length(glm::cross(reflected, toVertex)), 1e-6 * glm::length(toVertex))
      << "the reflected ray misses the vertex";
}

// Alhazen's circle problem solved by the sphere solver (another bracket and parametrisation) in the
// profile's plane: for a circular cylinder, R must project where the 2-D reflection point lies.
std::optional<glm::dvec3> circleReflectionPoint(const Extrusion& e, const glm::dvec3& eye, const glm::dvec3& vertex) {
  const auto flatten = [&](const glm::dvec3& p) {
    const glm::dvec3 offset = p - e.axisPoint;
    return glm::dvec3(glm::dot(offset, e.u), glm::dot(offset, e.v), 0.0);
  };
  return sphereReflectionPoint(Sphere{glm::dvec3(0.0), e.radii.x}, flatten(eye), flatten(vertex));
}

glm::dvec2 profileCoordinates(const Extrusion& e, const glm::dvec3& p) {
  const glm::dvec3 offset = p - e.axisPoint;
  return {glm::dot(offset, e.u), glm::dot(offset, e.v)};
}

}  // namespace

TEST(ExtrusionReflection, CylinderAgreesWithTheCircleSolutionAndTheLawOfReflection) {
  const Extrusion cylinder = Extrusion::along({0.3, -1.0, 0.5}, {0.0, 2.0, 0.0}, glm::dvec2(0.8));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-6.0, 6.0);
  int solved = 0, hidden = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 eye(coordinate(random), coordinate(random), coordinate(random));
    const glm::dvec3 vertex(coordinate(random), coordinate(random), coordinate(random));
    const auto r = extrusionReflectionPoint(cylinder, eye, vertex);
    const auto circle = circleReflectionPoint(cylinder, eye, vertex);
    ASSERT_EQ(r.has_value(), circle.has_value()) << "eye " << eye.x << ' ' << eye.y << ' ' << eye.z;
    if (!r) {
      ++hidden;
      continue;
    }
    ++solved;
    expectExactReflection(cylinder, eye, vertex, *r, 1e-9);
    EXPECT_NEAR(glm::distance(profileCoordinates(cylinder, r->position), glm::dvec2(*circle)), 0.0, 1e-9);
  }
  // Eyes or vertices inside the profile count as hidden; both outcomes must be well represented.
  EXPECT_GT(solved, 800);
  EXPECT_GT(hidden, 100);
}

TEST(ExtrusionReflection, EllipticAndObliqueExtrusionsSatisfyTheLawOfReflection) {
  const Extrusion ellipse = Extrusion::along({1.0, 0.0, -2.0}, {0.3, 1.0, 0.2}, {1.5, 0.4});
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-8.0, 8.0);
  int solved = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 eye(coordinate(random), coordinate(random), coordinate(random));
    const glm::dvec3 vertex(coordinate(random), coordinate(random), coordinate(random));
    if (const auto r = extrusionReflectionPoint(ellipse, eye, vertex)) {
      ++solved;
      expectExactReflection(ellipse, eye, vertex, *r, 1e-9);
    }
  }
  EXPECT_GT(solved, 800);
}

TEST(ExtrusionReflection, VertexInTheEyesShadowHasNoReflectionPoint) {
  const Extrusion cylinder = Extrusion::along({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, glm::dvec2(1.0));
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {5.0, 0.0, 0.0}, {-3.0, 2.0, 0.0}));  // straight behind
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {5.0, 0.0, 0.0}, {-1.5, 0.0, 0.5}));
  // Just outside the shadow's edge (the eye's tangent line) it is reflected near the silhouette.
  const double tangentSlope = 1.0 / std::sqrt(24.0);  // tangent from (5, 0): touches at x = 1/5
  const glm::dvec3 beside(-3.0, 0.0, -(5.0 + 3.0) * tangentSlope * 1.0001 - 1e-3);
  const auto r = extrusionReflectionPoint(cylinder, {5.0, 0.0, 0.0}, beside);
  ASSERT_TRUE(r);
  expectExactReflection(cylinder, {5.0, 0.0, 0.0}, beside, *r, 1e-8);
  EXPECT_NEAR(r->position.x, 0.2, 0.05) << "near the silhouette";
}

TEST(ExtrusionReflection, HardConfigurationsStayFiniteAndExact) {
  const Extrusion cylinder = Extrusion::along({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, glm::dvec2(1.0));
  // A far eye, grazing at the silhouette, a vertex touching the surface, a vertex on the eye's axis
  // plane, a vertex far along the extrusion.
  const glm::dvec3 cases[][2] = {{{1e4, 3.0, 2.0}, {0.0, 0.0, 3.0}},
                                 {{4.0, 0.0, 0.0}, {-3.0, 0.5, 7.0 / std::sqrt(15.0) + 1e-6}},
                                 {{4.0, 1.0, 1.0}, {1.0 + 1e-9, 0.0, 0.0}},
                                 {{4.0, 1.0, 0.0}, {2.0, -5.0, 0.0}},
                                 {{3.0, 0.0, 1.0}, {0.0, 1e4, 2.0}}};
  for (const auto& [eye, vertex] : cases) {
    const auto r = extrusionReflectionPoint(cylinder, eye, vertex);
    ASSERT_TRUE(r) << vertex.x << ' ' << vertex.y << ' ' << vertex.z;
    expectExactReflection(cylinder, eye, vertex, *r, 1e-7);
  }
  const double nan = std::nan("");
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {0.5, 3.0, 0.0}, {3.0, 0.0, 0.0})) << "eye inside the profile";
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {3.0, 0.0, 0.0}, {0.0, 2.0, 0.5})) << "vertex inside";
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {nan, 0.0, 0.0}, {3.0, 0.0, 0.0}));
  EXPECT_FALSE(extrusionReflectionPoint(cylinder, {3.0, 0.0, 0.0}, {0.0, INFINITY, 4.0}));
}

TEST(ExtrusionReflection, TransformedExtrusionIsTheMappedSurface) {
  const Extrusion object = Extrusion::along({0.2, 0.0, -0.1}, {0.0, 1.0, 0.0}, {0.5, 0.3});
  glm::dmat4 transform = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 3.0));
  transform = glm::rotate(transform, 0.7, glm::normalize(glm::dvec3(1.0, 1.0, 0.0)));
  transform = glm::scale(transform, glm::dvec3(2.0, 0.5, 1.3));
  transform[1][0] += 0.4;  // a shear: the mapped direction is no longer ⊥ the mapped profile
  const auto world = object.transformed(transform);
  ASSERT_TRUE(world);
  EXPECT_NEAR(glm::dot(world->u, world->v), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(world->u, world->direction), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(world->v, world->direction), 0.0, 1e-12);
  for (double t = 0.0; t < 6.28; t += 0.37)
    for (double height : {-1.0, 0.0, 2.5}) {
      const glm::dvec3 mapped = glm::dvec3(transform * glm::dvec4(object.pointAt(t, height), 1.0));
      EXPECT_NEAR(implicitValue(*world, mapped), 0.0, 1e-12);
      // Normals map by the inverse transpose.
      const glm::dvec3 normal =
          glm::normalize(glm::transpose(glm::inverse(glm::dmat3(transform))) * object.normalAt(t));
      EXPECT_NEAR(glm::length(normal - implicitNormal(*world, mapped)), 0.0, 1e-9);
    }
  EXPECT_FALSE(object.transformed(glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, 0.0)))) << "flattened profile";
}
