// Parametric mirrors (issue #19): the chrome Utah teapot, 32 Bézier patches tessellated for the view
// with every G-buffer texel evaluated on the exact patch, against the ray tracer (which intersects the
// patches themselves) and its reflection points against the exact patch solver (itself held to the
// law of reflection in tests/unit/ParametricSurfaceTest.cpp): searched, the general path, and as
// the planner renders it by default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "bench/ReflectionAccuracy.h"
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
    const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
    measured.worstMismatch = std::max(measured.worstMismatch, mismatch.share);
  }
  std::printf("%zu points: p50 %.4f px, p90 %.4f px, p95 %.4f px, p99 %.4f px, max %.4f px; worst mirror mismatch %.3f %%\n",
              measured.points.pixels.size(), measured.points.percentile(0.5), measured.points.percentile(0.9),
              measured.points.percentile(0.95), measured.points.percentile(0.99), measured.points.percentile(1.0),
              100.0 * measured.worstMismatch);
  return measured;
}

}  // namespace

TEST(ParametricMirror, SearchedTeapotMatchesTheRayTracedPatches) {
  passes::ReflectionSettings settings;
  settings.rayCast = passes::RayCastRule::Never;
  const Measured measured = measure(settings);
  EXPECT_GT(measured.points.pixels.size(), 500u);
  // Measured p99 0.04 px, issue #19's bound 0.5 px. Before the search held outline points on the
  // thin spout and handle to the exact surface, p90 was 59 px (README, Known limits).
  EXPECT_LE(measured.points.percentile(0.5), 0.01);
  EXPECT_LE(measured.points.percentile(0.99), 0.5);
  // The worst too (measured 0.006 px): points Newton reached past a patch's edge (on its polynomial's
  // continuation beyond a crease) or by a fold, where the normal nearly bisects at no reflection
  // point, were taken for reflections and lay 15 px from any until the search refused them.
  EXPECT_LE(measured.points.percentile(1.0), 0.5);
  // Measured 0.85 %, issue #19's bound 1.5 % (3.75 % while the mirror's rays met its own grid's
  // chords by their start: passes::ReflectionResources::meshBvh).
  EXPECT_LE(measured.worstMismatch, 0.015);
}

TEST(ParametricMirror, DefaultPlanMatchesTheRayTracedPatches) {
  const Measured measured = measure(passes::ReflectionSettings{});
  EXPECT_LE(measured.worstMismatch, 0.015);  // measured 0.58 %
}
