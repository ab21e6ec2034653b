// Parametric mirrors (issue #19): the chrome Utah teapot, 32 Bézier patches tessellated for the view
// with every G-buffer texel evaluated on the exact patch, against the ray tracer (which intersects the
// patches themselves) and its reflection points against the exact patch solver (itself held to the
// law of reflection in tests/unit/ParametricSurfaceTest.cpp): searched, the general path, and as
// the planner renders it by default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "bench/ReflectionAccuracy.h"
#include "scene/ParametricMesh.h"
#include "scene/Primitives.h"
#include "scene/builtin/SceneAssembly.h"
#include "SceneRig.h"

using namespace specula;

namespace {

struct Measured {
  double worstMismatch = 0.0;
  bench::ReflectionPointErrors points;
};

// Two poses along the teapot scene's orbit at 320x240.
Measured measure(const passes::ReflectionSettings& settings) {
  const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("utah-teapot"));
  Measured measured;
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  EXPECT_TRUE(rig.renderer);
  if (!rig.renderer) return measured;
  for (double t : {0.0, 7.0}) {
    const scene::ScenePose pose = scene::ScenePose::at(*scene, t);
    auto frame = rig.renderer->render(pose, 320, 240, settings);
    EXPECT_TRUE(frame) << frame.error();
    if (!frame) return measured;
    const bench::ReflectionPointErrors errors = bench::measureReflectionPoints(*rig.renderer, pose, *frame);
    measured.points.pixels.insert(measured.points.pixels.end(), errors.pixels.begin(), errors.pixels.end());
    measured.points.searchHiddenButExactVisible += errors.searchHiddenButExactVisible;
    measured.points.exactHiddenButSearchVisible += errors.exactHiddenButSearchVisible;
    const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
    measured.worstMismatch = std::max(measured.worstMismatch, mismatch.share);
  }
  std::printf(
      "%zu points: p50 %.4f px, p90 %.4f px, p95 %.4f px, p99 %.4f px, max %.4f px; %d hidden although reflected, "
      "%d reflected where none is; worst mirror mismatch %.3f %%\n",
      measured.points.pixels.size(), measured.points.percentile(0.5), measured.points.percentile(0.9),
      measured.points.percentile(0.95), measured.points.percentile(0.99), measured.points.percentile(1.0),
      measured.points.searchHiddenButExactVisible, measured.points.exactHiddenButSearchVisible,
      100.0 * measured.worstMismatch);
  return measured;
}

// A convex cap y = −(x² + z²)/2 over [−½, ½]², facing +y, as two bicubic patches meeting along x = 0.
// `crease` > 0 bends the second (x > 0) down from the seam, so the normal jumps there by about that
// many radians and the directions between the two sides reflect nowhere: the teapot's lid seam in
// small (0.004 rad there). 0: the seam is smooth (the patches are one cubic cut in two).
std::vector<math::BezierPatch> twoPatchCap(double crease) {
  // Bézier coefficients of −t²/2 on [−½, ½] as a cubic, and the positions of the control rows.
  const double height[4] = {-0.125, 0.125 / 3.0, 0.125 / 3.0, -0.125};
  math::BezierPatch whole;
  for (int row = 0; row < 4; ++row)             // v: along x
    for (int column = 0; column < 4; ++column)  // u: along z, so du × dv points up
      whole.points[static_cast<std::size_t>(4 * row + column)] = {-0.5 + row / 3.0, height[row] + height[column],
                                                                  -0.5 + column / 3.0};
  math::BezierPatch left = whole.restricted(0.0, 1.0, 0.0, 0.5), right = whole.restricted(0.0, 1.0, 0.5, 1.0);
  const double rowSpacing = 0.5 / 3.0;  // of the right patch's control rows, along x
  for (int column = 0; column < 4; ++column)
    right.points[static_cast<std::size_t>(4 + column)].y -= crease * rowSpacing;
  return {left, right};
}

// The cap as a mirror seen from (−3, 4, 0), and a dense strip of vertices at height 4 across the
// directions its seam reflects: one every 0.0002 units, so some land wherever the reflection of
// the seam's neighbourhood can go.
std::shared_ptr<const scene::Scene> capScene(double crease) {
  scene::Scene cap;
  cap.name = "two-patch-cap";
  cap.background = {0.2f, 0.2f, 0.3f};
  cap.lights.push_back(scene::builtin::sunLight({0.3f, 1.0f, 0.2f}, 1.0f));
  cap.camera = {{-3.0f, 4.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 25.0f};
  const std::uint32_t mirror = scene::builtin::addObject(
      cap, "cap", scene::builtin::addMesh(cap, scene::parametricMesh("cap", twoPatchCap(crease))),
      scene::builtin::addMaterial(cap, scene::builtin::perfectMirror("chrome")));
  cap.objects[mirror].mirror =
      scene::MirrorInfo{scene::MirrorCurvature::Convex, true, std::nullopt, std::nullopt, std::nullopt};
  cap.objects[mirror].reflected = false;
  // The seam's own reflection at the cap's top leaves along (0.6, 0.8, 0) and meets y = 4 at x = 3.
  scene::builtin::addObject(cap, "strip",
                            scene::builtin::addMesh(cap, scene::primitives::grid("strip", 0.4f, 0.02f, 2000, 2)),
                            scene::builtin::addMaterial(cap, scene::builtin::matte("orange", 0xE08020)),
                            scene::builtin::placed({3.0f, 4.0f, 0.0f}));
  return std::make_shared<const scene::Scene>(std::move(cap));
}

// The cap searched: every reflection found where it lies, none where there is none.
void expectCapSearchedExactly(double crease) {
  const auto scene = capScene(crease);
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto frame = rig.renderer->render(pose, 320, 240, specula::testing::virtualObjects());
  ASSERT_TRUE(frame) << frame.error();
  const bench::ReflectionPointErrors errors = bench::measureReflectionPoints(*rig.renderer, pose, *frame);
  std::printf("crease %.3f rad: %zu points, max %.4f px; %d reflected where none is, %d hidden although reflected\n",
              crease, errors.pixels.size(), errors.percentile(1.0), errors.exactHiddenButSearchVisible,
              errors.searchHiddenButExactVisible);
  EXPECT_GT(errors.pixels.size(), 2000u);
  EXPECT_LE(errors.percentile(1.0), 0.5);
  EXPECT_EQ(errors.exactHiddenButSearchVisible, 0);
  EXPECT_EQ(errors.searchHiddenButExactVisible, 0);
}

}  // namespace

// Across a smooth seam the answer lies on the neighbour patch, where Newton's method on the exact
// patch goes on from (the G-buffer holds the patches' adjacency): no reflection may be lost there.
TEST(ParametricMirror, ReflectionsAcrossASmoothSeamAreFound) { expectCapSearchedExactly(0.0); }

// By a crease no point of either patch reflects the directions between its two normals; each patch's
// polynomial, continued past the seam, does, just beyond its edge. Those roots are not reflections.
TEST(ParametricMirror, NoReflectionIsTakenFromPastACrease) { expectCapSearchedExactly(0.01); }

TEST(ParametricMirror, SearchedTeapotMatchesTheRayTracedPatches) {
  passes::ReflectionSettings settings;
  settings.rayCast = passes::RayCastRule::Never;
  const Measured measured = measure(settings);
  EXPECT_GT(measured.points.pixels.size(), 500u);
  // Measured p99 0.001 px, issue #19's bound 0.5 px: the thin spout and handle hold only because the
  // search takes outline points to the exact surface.
  EXPECT_LE(measured.points.percentile(0.5), 0.01);
  EXPECT_LE(measured.points.percentile(0.99), 0.5);
  // The worst too (measured 0.006 px): points Newton reached past a patch's edge (on its polynomial's
  // continuation beyond a crease: NoReflectionIsTakenFromPastACrease) or by a fold, where the normal
  // nearly bisects at no reflection point, were taken for reflections and lay 15 px from any until
  // the search refused them.
  EXPECT_LE(measured.points.percentile(1.0), 0.5);
  // Measured 0.85 %, issue #19's bound 1.5 % (3.75 % while the mirror's rays met its own grid's
  // chords by their start: passes::ReflectionResources::meshBvh).
  EXPECT_LE(measured.worstMismatch, 0.015);
}

TEST(ParametricMirror, DefaultPlanMatchesTheRayTracedPatches) {
  const Measured measured = measure(passes::ReflectionSettings{});
  EXPECT_LE(measured.worstMismatch, 0.015);  // measured 0.58 %
}
