// Bézier patches and B-spline surfaces (math/BezierPatch, math/BSplineSurface), the exact reflection
// solver on patches (math/PatchReflection) and the Utah teapot's data, against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "math/BSplineSurface.h"
#include "math/BezierPatch.h"
#include "math/PatchReflection.h"
#include "scene/ParametricMesh.h"
#include "scene/builtin/UtahTeapot.h"

namespace specula {
namespace {

using math::BezierPatch;

// The bilinear map origin + u·a + v·b written as a bicubic patch (control points at thirds).
BezierPatch planePatch(const glm::dvec3& origin, const glm::dvec3& a, const glm::dvec3& b) {
  BezierPatch patch;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      patch.points[static_cast<std::size_t>(4 * row + column)] = origin + (column / 3.0) * a + (row / 3.0) * b;
  return patch;
}

TEST(BezierPatch, BilinearPlaneEvaluatesToItsClosedForm) {
  const glm::dvec3 origin(1.0, -2.0, 0.5), a(3.0, 0.5, 0.0), b(-0.5, 0.25, 2.0);
  const BezierPatch patch = planePatch(origin, a, b);
  for (double u : {0.0, 0.2, 0.5, 0.93, 1.0})
    for (double v : {0.0, 0.4, 0.77, 1.0}) {
      const math::PatchSample s = patch.sample(u, v);
      const glm::dvec3 expected = origin + u * a + v * b;
      EXPECT_NEAR(glm::length(s.position - expected), 0.0, 1e-12) << u << ", " << v;
      EXPECT_NEAR(glm::length(s.du - a), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(s.dv - b), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(s.normal - glm::normalize(glm::cross(a, b))), 0.0, 1e-12);
    }
}

TEST(BezierPatch, RestrictedPieceIsTheSameSurface) {
  const std::vector<BezierPatch> teapot = scene::builtin::utahTeapotPatches();
  const BezierPatch& body = teapot[4];
  const BezierPatch piece = body.restricted(0.25, 0.5, 0.5, 0.875);
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0})
      EXPECT_NEAR(glm::length(piece.position(u, v) - body.position(0.25 + 0.25 * u, 0.5 + 0.375 * v)), 0.0, 1e-12);
}

TEST(BezierPatch, RayMeetsPlanePatchWhereTheClosedFormSays) {
  const BezierPatch patch = planePatch({0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.0, 0.0, -2.0});  // y = 0, facing +y
  const glm::dvec3 origin(0.5, 3.0, -0.2), direction = glm::normalize(glm::dvec3(0.3, -1.0, -0.4));
  const auto hit = math::intersectPatch(patch, origin, direction, 0.0, 100.0);
  ASSERT_TRUE(hit);
  const double t = 3.0 / -direction.y;
  EXPECT_NEAR(hit->t, t, 1e-10);
  const glm::dvec3 point = origin + t * direction;
  EXPECT_NEAR(hit->uv.x, point.x / 2.0, 1e-10);
  EXPECT_NEAR(hit->uv.y, -point.z / 2.0, 1e-10);
  // Outside the patch, or beyond tMax: no hit.
  EXPECT_FALSE(math::intersectPatch(patch, {5.0, 3.0, 0.0}, {0.0, -1.0, 0.0}, 0.0, 100.0));
  EXPECT_FALSE(math::intersectPatch(patch, origin, direction, 0.0, 0.5 * t));
}

// y = 2x − x², x in [0, 2], extruded along z over [0, 1]: a quadratic B-spline of two spans whose
// control points are the parabola's blossoms.
math::BSplineSurface parabolicSheet() {
  math::BSplineSurface surface;
  surface.degree = {2, 1};
  surface.count = {4, 2};
  surface.knotsU = {0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0};
  surface.knotsV = {0.0, 0.0, 1.0, 1.0};
  for (double z : {0.0, 1.0})
    for (const glm::dvec2 xy : {glm::dvec2(0.0, 0.0), glm::dvec2(0.5, 1.0), glm::dvec2(1.5, 1.0), glm::dvec2(2.0, 0.0)})
      surface.controlNet.emplace_back(xy.x, xy.y, z);
  return surface;
}

TEST(BSplineSurface, QuadraticSplineReproducesTheParabolaItsBlossomsDescribe) {
  const math::BSplineSurface surface = parabolicSheet();
  ASSERT_EQ(math::bsplineProblem(surface), std::nullopt);
  const std::vector<BezierPatch> patches = math::bezierPatchesOf(surface);
  ASSERT_EQ(patches.size(), 2u);  // two spans along u, one along v
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (double u = 0.0; u <= 1.0; u += 0.125)
      for (double v : {0.0, 0.5, 1.0}) {
        const glm::dvec3 s = patches[p].position(u, v);
        EXPECT_NEAR(s.y, 2.0 * s.x - s.x * s.x, 1e-12) << "patch " << p << " at " << u;
        EXPECT_NEAR(s.z, v, 1e-12);
        EXPECT_NEAR(s.x, static_cast<double>(p) + u, 1e-12);  // x = 2t over the knot parameter t, spans of 0.5
      }
  // The spans meet without a gap.
  EXPECT_NEAR(glm::length(patches[0].position(1.0, 0.3) - patches[1].position(0.0, 0.3)), 0.0, 1e-12);
}

TEST(BSplineSurface, GarbageIsRefusedByName) {
  const auto problemWith = [](auto change) {
    math::BSplineSurface surface = parabolicSheet();
    change(surface);
    return math::bsplineProblem(surface).value_or("");
  };
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.degree.x = 4; }).find("degree along u"), std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.knotsU.pop_back(); }).find("knots along u has 6 knots"),
            std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) {
              s.knotsV = {0.0, 1.0, 0.5, 1.0};
            }).find("must not decrease"),
            std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.knotsU = {0, 0, 0, 0, 0, 0, 0}; }).find("no domain"),
            std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.controlNet.pop_back(); }).find("control net has 7 points"),
            std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.controlNet[3].y = std::nan(""); }).find("control point 3"),
            std::string::npos);
  EXPECT_NE(problemWith([](math::BSplineSurface& s) { s.knotsU[2] = INFINITY; }).find("not a finite"),
            std::string::npos);
}

TEST(PatchReflection, PlaneMirrorMatchesTheMirroredVertexConstruction) {
  const math::PatchReflectionSolver solver({planePatch({-2.0, 0.0, 2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, -4.0})});
  const glm::dvec3 eye(0.3, 1.0, 0.2), vertex(-0.5, 2.0, 0.4);
  const auto points = solver.solve(eye, vertex);
  ASSERT_EQ(points.size(), 1u);
  // The eye's ray to the vertex mirrored below the plane crosses it a third of the way down.
  const glm::dvec3 expected = eye + (glm::dvec3(vertex.x, -vertex.y, vertex.z) - eye) / 3.0;
  EXPECT_NEAR(glm::length(points[0].position - expected), 0.0, 1e-9);
  // From behind the mirror there is no reflection.
  EXPECT_TRUE(solver.solve(eye, {0.0, -1.0, 0.0}).empty());
}

// The reflected ray at every reflection point found must pass through the vertex.
TEST(PatchReflection, TeapotReflectionPointsObeyTheLawOfReflection) {
  const math::PatchReflectionSolver solver(scene::builtin::utahTeapotPatches());
  const glm::dvec3 eye(6.0, 4.4, 6.4);
  int found = 0;
  for (const glm::dvec3 vertex : {glm::dvec3(1.5, 0.8, -4.2), glm::dvec3(-4.0, 1.0, 2.2), glm::dvec3(4.6, 0.3, 1.0),
                                  glm::dvec3(0.0, 8.0, 0.0), glm::dvec3(3.0, 2.5, 0.0)})
    for (const math::PatchPoint& r : solver.solve(eye, vertex)) {
      ++found;
      const glm::dvec3 in = glm::normalize(r.position - eye);
      const glm::dvec3 out = in - 2.0 * glm::dot(in, r.normal) * r.normal;
      const glm::dvec3 toVertex = vertex - r.position;
      EXPECT_NEAR(glm::length(glm::cross(out, toVertex)) / glm::length(toVertex), 0.0, 1e-9);
      EXPECT_GT(glm::dot(out, toVertex), 0.0);
    }
  EXPECT_GE(found, 5);  // each vertex is seen at least once in a convex body
}

// From near a reflection point, Newton's method lands on it; from behind the mirror, on nothing.
TEST(PatchReflection, SolvingNearAPointFindsTheReflectionThere) {
  const math::PatchReflectionSolver solver({planePatch({-2.0, 0.0, 2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, -4.0})});
  const glm::dvec3 eye(0.3, 1.0, 0.2), vertex(-0.5, 2.0, 0.4);
  const glm::dvec3 expected = eye + (glm::dvec3(vertex.x, -vertex.y, vertex.z) - eye) / 3.0;
  const auto near = solver.solveNear(eye, vertex, expected + glm::dvec3(0.3, 0.05, -0.2));
  ASSERT_TRUE(near);
  EXPECT_NEAR(glm::length(near->position - expected), 0.0, 1e-9);
  EXPECT_FALSE(solver.solveNear(eye, {0.0, -1.0, 0.0}, expected));
  // On the teapot every point it returns obeys the law of reflection, whichever sample it starts from.
  const math::PatchReflectionSolver teapot(scene::builtin::utahTeapotPatches());
  const glm::dvec3 teapotEye(6.0, 4.4, 6.4), teapotVertex(4.6, 0.3, 1.0);
  int found = 0;
  for (const math::PatchPoint& start : teapot.solve(teapotEye, teapotVertex)) {
    const auto again = teapot.solveNear(teapotEye, teapotVertex, start.position);
    ASSERT_TRUE(again);
    EXPECT_NEAR(glm::length(again->position - start.position), 0.0, 1e-6);
    ++found;
  }
  EXPECT_GE(found, 1);
}

// A grid's chords stray from a smooth surface by the square of their length: half the segments,
// four times the deviation; a flat patch's grid lies on it.
TEST(ParametricMesh, GridDeviationFallsWithTheSquareOfTheSegments) {
  const scene::Mesh coarse = scene::parametricMesh("teapot", scene::builtin::utahTeapotPatches(), 8);
  const scene::Mesh fine = scene::parametricMesh("teapot", scene::builtin::utahTeapotPatches(), 16);
  EXPECT_GT(fine.gridDeviation, 0.0);
  EXPECT_NEAR(coarse.gridDeviation / fine.gridDeviation, 4.0, 1.0);
  const scene::Mesh flat =
      scene::parametricMesh("plane", {planePatch({-2.0, 0.0, 2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, -4.0})}, 4);
  EXPECT_NEAR(flat.gridDeviation, 0.0, 1e-12);
}

TEST(UtahTeapot, ThirtyTwoPatchesStandingOnTheFloorFacingOutwards) {
  const std::vector<BezierPatch> patches = scene::builtin::utahTeapotPatches();
  ASSERT_EQ(patches.size(), 32u);
  glm::dvec3 low(1e9), high(-1e9);
  for (const BezierPatch& patch : patches) {
    const auto [l, h] = patch.controlBounds();
    low = glm::min(low, l);
    high = glm::max(high, h);
  }
  EXPECT_DOUBLE_EQ(low.y, 0.0);
  EXPECT_DOUBLE_EQ(high.y, 3.15);
  EXPECT_DOUBLE_EQ(high.x, 3.525);  // the spout's lip, along +x
  EXPECT_DOUBLE_EQ(low.x, -3.0);    // the handle
  // Patches come in the data's order, four copies each of rim, upper and lower body, knob, lid and
  // bottom: at the body's centres the normal points away from the axis, at the bottom's down.
  for (std::size_t p = 4; p < 12; ++p) {
    const math::PatchSample s = patches[p].sample(0.5, 0.5);
    EXPECT_GT(glm::dot(s.normal, glm::normalize(glm::dvec3(s.position.x, 0.0, s.position.z))), 0.6) << "patch " << p;
  }
  for (std::size_t p = 20; p < 24; ++p) EXPECT_LT(patches[p].sample(0.5, 0.5).normal.y, -0.9) << "patch " << p;
  // Closed enough to enclose a positive volume with outward fronts (divergence theorem on the grid).
  const scene::Mesh mesh = scene::parametricMesh("teapot", patches, 12);
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[3 * t]].position), b(mesh.vertices[mesh.indices[3 * t + 1]].position),
        c(mesh.vertices[mesh.indices[3 * t + 2]].position);
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  EXPECT_GT(volume, 20.0);
  EXPECT_LT(volume, 40.0);
  EXPECT_EQ(scene::patchOfTriangle(mesh, mesh.triangleCount() - 1), 31u);
  EXPECT_EQ(scene::patchOfTriangle(mesh, 2 * 12 * 12), 1u);
}

}  // namespace
}  // namespace specula
