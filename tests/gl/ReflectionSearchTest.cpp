// The screen-space reflection-point search against independent answers: the exact sphere solver
// (server/math) for reflection points, the Embree ray tracer (server/reference) for whole frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "bench/ReflectionAccuracy.h"
#include "gl/GlContext.h"
#include "math/Reflection.h"
#include "reference/ImageMetrics.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"

using namespace specula;
using specula::bench::measureReflectionPoints;
using specula::bench::toPixels;

namespace {

struct Rig {
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
};

Rig makeRig(const std::string& sceneName) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  EXPECT_TRUE(context) << context.error();
  if (!context) return {};
  auto renderer = render::Renderer::create(**context, std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(sceneName)));
  EXPECT_TRUE(renderer) << renderer.error();
  if (!renderer) return {};
  return {std::move(context.value()), std::move(renderer.value())};
}

}  // namespace

class SearchAccuracyTest : public ::testing::TestWithParam<const char*> {};

// Bounds measured on llvmpipe at 640×480 (p50 ≈ 0.002 px, p99 ≤ 0.75 px, max ≤ 1.6 px), with margin;
// the largest errors are grazing reflection points next to the silhouette.
TEST_P(SearchAccuracyTest, ReflectionPointsAgreeWithTheExactSphereSolver) {
  Rig rig = makeRig(GetParam());
  for (double t : {0.0, 0.5}) {
    const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), t);
    auto frame = rig.renderer->render(pose, 640, 480);
    ASSERT_TRUE(frame) << frame.error();
    const auto errors = measureReflectionPoints(*rig.renderer, pose, *frame);
    ASSERT_GT(errors.pixels.size(), 2u);
    EXPECT_LE(errors.percentile(0.5), 0.02) << "t=" << t;
    EXPECT_LE(errors.percentile(0.99), 1.0) << "t=" << t;
    EXPECT_LE(errors.percentile(1.0), 2.0) << "t=" << t;
    EXPECT_EQ(errors.exactHiddenButSearchVisible, 0) << "a hidden vertex was reflected as if visible";
    EXPECT_LE(errors.searchHiddenButExactVisible, static_cast<int>(errors.pixels.size() / 30) + 1)
        << "only grazing vertices may be misjudged hidden";
    EXPECT_EQ(frame->search.unsolved, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(AnalyticSpheres, SearchAccuracyTest, ::testing::Values("checker-sphere", "teapot-table", "quad"),
                         [](const auto& param) {
                           std::string name = param.param;
                           std::erase(name, '-');
                           return name;
                         });

TEST(ReflectionSearch, GlslVirtualVertexMatchesItsCppTwinOnTheSameInputs) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::Scene& scene = rig.renderer->scene();
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240));
  const auto results = rig.renderer->readReflectedVertices();
  const passes::ReflectionSlotRange& range = rig.renderer->reflectionSlots().mirrors[0].reflected[0];
  const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
  int compared = 0, hidden = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const passes::ReflectedVertex& result = results[range.firstSlot + v];
    if (result.state.w & passes::ReflectedVertex::kUnsolved) continue;
    const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
    const glm::dvec3 r(result.reflectionPoint);
    const glm::dvec3 expected = (result.state.w & passes::ReflectedVertex::kHidden)
                                    ? math::mirrorAcrossPlane(r, glm::dvec3(result.reflectionNormal), vertex)
                                    : math::virtualVertex(glm::dvec3(pose.camera.eye), r, vertex);
    EXPECT_LT(glm::length(expected - glm::dvec3(result.virtualPosition)), 1e-4 * (1.0 + glm::length(expected)));
    hidden += (result.state.w & passes::ReflectedVertex::kHidden) != 0;
    ++compared;
  }
  EXPECT_GT(hidden, 0);
  EXPECT_GT(compared, 200);
}

TEST(ReflectionSearch, HiddenVerticesAreFlaggedAndStillGetAFiniteVirtualPosition) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  auto frame = rig.renderer->render(pose, 320, 240);
  ASSERT_TRUE(frame);
  EXPECT_GT(frame->search.hidden, 0u) << "the floor behind the sphere is region C";
  for (const passes::ReflectedVertex& result : rig.renderer->readReflectedVertices()) {
    if (!(result.state.w & passes::ReflectedVertex::kHidden)) continue;
    EXPECT_EQ(result.virtualPosition.w, 1.0f);
    for (int axis = 0; axis < 3; ++axis) EXPECT_TRUE(std::isfinite(result.virtualPosition[axis]));
  }
}

TEST(ReflectionSearch, CoherenceMakesTheNextFrameCheapAndResetStartsCold) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  auto cold = rig.renderer->render(pose, 640, 480);
  auto warm = rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), 1.0 / 60.0), 640, 480);
  ASSERT_TRUE(cold && warm);
  EXPECT_EQ(cold->search.coldStarts, cold->search.searched);
  EXPECT_EQ(warm->search.coldStarts, 0u);
  EXPECT_LE(static_cast<double>(warm->search.totalSteps) / warm->search.searched, 5.0);
  rig.renderer->resetCoherence();
  auto reset = rig.renderer->render(pose, 640, 480);
  ASSERT_TRUE(reset);
  EXPECT_EQ(reset->search.coldStarts, reset->search.searched);
}

TEST(ReflectionSearch, ColdStartsClimbThePyramidInFewStepsAt1280x720) {
  Rig rig = makeRig("teapot-table");
  ASSERT_TRUE(rig.renderer);
  passes::ReflectionSettings settings;
  settings.coherence = false;
  auto frame = rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), 0.0), 1280, 720, settings);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->search.coldStarts, frame->search.searched);
  // A naive walk from the mirror centre needs ~110 windows here (issue #3); the pyramid about 20.
  EXPECT_LE(static_cast<double>(frame->search.totalSteps) / frame->search.searched, 22.0);
}

TEST(ReflectionSearch, PartlyVisibleMirrorReflectsCorrectlyAtTheScreenEdge) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  // Turn the view right by nearly half the horizontal field so the sphere's centre sits at the left edge.
  const glm::vec3 toSphere = glm::normalize(glm::vec3(0.0f) - pose.camera.eye);
  const glm::vec3 right = glm::normalize(glm::cross(toSphere, pose.camera.up));
  const float halfWidth = 0.95f * std::atan(std::tan(glm::radians(pose.camera.fovYDegrees) / 2.0f) * 640.0f / 480.0f);
  pose.camera.target = pose.camera.eye + std::cos(halfWidth) * toSphere + std::sin(halfWidth) * right;
  auto frame = rig.renderer->render(pose, 640, 480);
  ASSERT_TRUE(frame);
  const glm::dvec2 center = toPixels(frame->view, glm::vec3(0.0f), 640, 480);
  ASSERT_TRUE(center.x > -5.0 && center.x < 40.0) << "the test needs the mirror cut by the left edge, centre at " << center.x;
  const auto errors = measureReflectionPoints(*rig.renderer, pose, *frame);
  ASSERT_GT(errors.pixels.size(), 20u);
  EXPECT_LE(errors.percentile(0.99), 1.0);
  EXPECT_EQ(frame->search.unsolved, 0u);
}

// The issue asks that no virtual vertex jump more than 2 px between frames; near the silhouette the
// true reflection itself moves up to 1.7 px a frame on this path, so the bound is on how much
// further than the truth a vertex moves. The search's error must also not wander between frames.
TEST(ReflectionSearch, VirtualVerticesMoveWithTheTruthAlongASmoothCameraPath) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  std::map<std::size_t, bench::MeasuredVertex> previousBySlot;
  std::vector<double> errorJumps;
  double largestExcess = 0.0, largestMove = 0.0;
  for (int step = 0; step < 12; ++step) {  // the scene's camera orbit at 60 frames per second
    const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), step / 60.0);
    auto frame = rig.renderer->render(pose, 640, 480);
    ASSERT_TRUE(frame);
    const auto errors = measureReflectionPoints(*rig.renderer, pose, *frame);
    std::map<std::size_t, bench::MeasuredVertex> bySlot;
    for (const bench::MeasuredVertex& vertex : errors.vertices) {
      bySlot[vertex.slot] = vertex;
      const auto previous = previousBySlot.find(vertex.slot);
      if (previous == previousBySlot.end()) continue;
      const glm::dvec2 exactMove = vertex.exact - previous->second.exact;
      const double searchMove = glm::length(exactMove + vertex.offset - previous->second.offset);
      largestMove = std::max(largestMove, searchMove);
      largestExcess = std::max(largestExcess, searchMove - glm::length(exactMove));
      errorJumps.push_back(glm::length(vertex.offset - previous->second.offset));
    }
    previousBySlot = std::move(bySlot);
  }
  ASSERT_GT(errorJumps.size(), 1000u);
  EXPECT_GT(largestMove, 0.5) << "the camera moved, so reflections must move";
  EXPECT_LE(largestExcess, 2.0);
  // Measured: error jumps p50 < 0.001, p90 0.013 px; only grazing vertices wander more.
  std::sort(errorJumps.begin(), errorJumps.end());
  EXPECT_LE(errorJumps[errorJumps.size() / 2], 0.01);
  EXPECT_LE(errorJumps[errorJumps.size() * 9 / 10], 0.05);
}

TEST(ReflectionSearch, CheckerSphereFrameAgreesWithTheRayTracedReference) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  auto frame = rig.renderer->render(pose, 320, 240);
  ASSERT_TRUE(frame);
  auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(rig.renderer->scene()));
  ASSERT_TRUE(tracer) << tracer.error();
  auto truth = (*tracer)->render(pose, {320, 240, 1, 0});
  ASSERT_TRUE(truth) << truth.error();
  const reference::RgbaView ours{frame->rgba, 320, 240}, theirs{truth->rgba, 320, 240};
  auto mismatch = reference::maskedMismatch(ours, theirs, truth->mirrorMask);
  ASSERT_TRUE(mismatch);
  // Measured 0.11 / 19.1 dB / 0.94: the rest is the coarse floor's straight virtual edges, which
  // adaptive tessellation (issue #4) removes.
  EXPECT_GT(mismatch->inside, 10000u);
  EXPECT_LE(mismatch->share(), 0.14);
  EXPECT_GE(*reference::psnr(ours, theirs), 18.0);
  EXPECT_GE(*reference::ssim(ours, theirs), 0.93);
  // Outside the mirror the two renderers agree to the byte (±1 for sRGB rounding).
  for (std::size_t i = 0; i < truth->mirrorMask.size(); ++i) {
    if (truth->mirrorMask[i]) continue;
    for (int c = 0; c < 3; ++c) ASSERT_LE(std::abs(frame->rgba[i * 4 + c] - truth->rgba[i * 4 + c]), 1) << "pixel " << i;
  }
}

TEST(ReflectionSearch, SeveralMovingMirrorsAreSearchedEveryFrame) {
  Rig rig = makeRig("ants");
  ASSERT_TRUE(rig.renderer);
  for (double t : {0.0, 0.25, 0.5}) {
    auto frame = rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), t), 320, 240);
    ASSERT_TRUE(frame);
    EXPECT_GE(frame->drawnMirrors.size(), 2u);
    EXPECT_EQ(frame->search.unsolved, 0u);
    EXPECT_GT(frame->search.searched, 0u);
  }
}
