// The screen-space reflection-point search against independent answers: the exact sphere solver
// (server/math) for reflection points, the Embree ray tracer (server/reference) for whole frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>
#include <vector>

#include "bench/ReflectionAccuracy.h"
#include "gl/GlContext.h"
#include "math/Reflection.h"
#include "reference/ImageMetrics.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "SceneRig.h"

using namespace specula;
using specula::bench::measureReflectionPoints;
using specula::bench::toPixels;
using specula::testing::makeRig;
using specula::testing::Rig;
using specula::testing::searchName;
using specula::testing::virtualObjects;
using specula::testing::withSearch;

class SearchAccuracyTest : public ::testing::TestWithParam<std::tuple<const char*, passes::SearchStrategy>> {};

// Bounds measured on llvmpipe at 640×480 (p50 ≈ 1e-5 px, p99 ≤ 4e-5 px, max ≤ 0.005 px), with margin:
// either search finds the G-buffer texel, then refines on the mirror's exact quadric.
TEST_P(SearchAccuracyTest, ReflectionPointsAgreeWithTheExactSphereSolver) {
  const auto& [sceneName, search] = GetParam();
  Rig rig = makeRig(sceneName);
  for (double t : {0.0, 0.5}) {
    const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), t);
    auto frame = rig.renderer->render(pose, 640, 480, withSearch(search));
    ASSERT_TRUE(frame) << frame.error();
    const auto errors = measureReflectionPoints(*rig.renderer, pose, *frame);
    ASSERT_GT(errors.pixels.size(), 2u);
    EXPECT_LE(errors.percentile(0.5), 0.001) << "t=" << t;
    EXPECT_LE(errors.percentile(0.99), 0.01) << "t=" << t;
    EXPECT_LE(errors.percentile(1.0), 0.05) << "t=" << t;
    // Region C is decided exactly, in float: only vertices within rounding of the eye's tangent
    // cone may land on the other side (ants: a few of the head's vertices touching the eyes).
    EXPECT_LE(errors.exactHiddenButSearchVisible + errors.searchHiddenButExactVisible,
              static_cast<int>(errors.pixels.size() / 1000))
        << errors.exactHiddenButSearchVisible << " hidden judged visible, " << errors.searchHiddenButExactVisible
        << " visible judged hidden";
    EXPECT_EQ(frame->search.unsolved, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(AnalyticSpheres, SearchAccuracyTest,
                         ::testing::Combine(::testing::Values("checker-sphere", "teapot-table", "quad", "ants"),
                                            ::testing::ValuesIn(specula::testing::kSearchStrategies)),
                         [](const auto& param) {
                           std::string name =
                               std::string(std::get<0>(param.param)) + "_" + searchName(std::get<1>(param.param));
                           std::erase(name, '-');
                           return name;
                         });

TEST(ReflectionSearch, GlslVirtualVertexMatchesItsCppTwinOnTheSameInputs) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::Scene& scene = rig.renderer->scene();
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240, virtualObjects()));
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
  auto frame = rig.renderer->render(pose, 320, 240, virtualObjects());
  ASSERT_TRUE(frame);
  EXPECT_GT(frame->search.hidden, 0u) << "the floor behind the sphere is region C";
  const scene::Scene& scene = rig.renderer->scene();
  const passes::MirrorSlots& mirror = rig.renderer->reflectionSlots().mirrors[0];
  const glm::dvec3 center(pose.objectToWorld[mirror.mirrorObject] *
                          glm::vec4(scene.objects[mirror.mirrorObject].mirror->analytic->center, 1.0f));
  const double radius = glm::length(glm::vec3(pose.objectToWorld[mirror.mirrorObject][0])) *
                        scene.objects[mirror.mirrorObject].mirror->analytic->radii.x;
  const glm::dvec3 eye(pose.camera.eye);
  const passes::ReflectionSlotRange& range = mirror.reflected[0];
  const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
  const auto results = rig.renderer->readReflectedVertices();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const passes::ReflectedVertex& result = results[range.firstSlot + v];
    if (!(result.state.w & passes::ReflectedVertex::kHidden)) continue;
    EXPECT_EQ(result.virtualPosition.w, 1.0f);
    for (int axis = 0; axis < 3; ++axis) EXPECT_TRUE(std::isfinite(result.virtualPosition[axis]));
    // Reflected from the silhouette point in the plane of eye, centre and vertex, on its side.
    const glm::dvec3 r(result.reflectionPoint),
        vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
    EXPECT_NEAR(glm::length(r - center), radius, 1e-4 * radius);
    EXPECT_NEAR(glm::dot(glm::normalize(r - eye), glm::normalize(r - center)), 0.0, 1e-4) << "not on the silhouette";
    const glm::dvec3 planeNormal = glm::normalize(glm::cross(center - eye, vertex - eye));
    EXPECT_NEAR(glm::dot(r - eye, planeNormal), 0.0, 1e-4 * radius) << "not in the plane of eye, centre and vertex";
    EXPECT_GT(glm::dot(r - center, vertex - center), 0.0) << "the silhouette point is on the side away from the vertex";
  }
}

TEST(ReflectionSearch, CoherenceMakesTheNextFrameCheapAndResetStartsCold) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  auto cold = rig.renderer->render(pose, 640, 480, virtualObjects());
  auto warm = rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), 1.0 / 60.0), 640, 480, virtualObjects());
  ASSERT_TRUE(cold && warm);
  EXPECT_EQ(cold->search.coldStarts, cold->search.searched);
  EXPECT_EQ(warm->search.coldStarts, 0u);
  EXPECT_LE(static_cast<double>(warm->search.totalSteps) / warm->search.searched, 5.0);
  rig.renderer->resetCoherence();
  auto reset = rig.renderer->render(pose, 640, 480, virtualObjects());
  ASSERT_TRUE(reset);
  EXPECT_EQ(reset->search.coldStarts, reset->search.searched);
}

TEST(ReflectionSearch, ColdStartsClimbThePyramidInFewStepsAt1280x720) {
  Rig rig = makeRig("teapot-table");
  ASSERT_TRUE(rig.renderer);
  passes::ReflectionSettings settings;
  settings.coherence = false;
  auto frame =
      rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), 0.0), 1280, 720, virtualObjects(settings));
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
  auto frame = rig.renderer->render(pose, 640, 480, virtualObjects());
  ASSERT_TRUE(frame);
  const glm::dvec2 center = toPixels(frame->view, glm::vec3(0.0f), 640, 480);
  ASSERT_TRUE(center.x > -5.0 && center.x < 40.0)
      << "the test needs the mirror cut by the left edge, centre at " << center.x;
  const auto errors = measureReflectionPoints(*rig.renderer, pose, *frame);
  ASSERT_GT(errors.pixels.size(), 20u);
  EXPECT_LE(errors.percentile(1.0), 0.05);
  EXPECT_EQ(frame->search.unsolved, 0u);
}

namespace {

// How far virtual vertices move between consecutive frames of the scene's camera orbit.
struct PathJumps {
  double visible = 0.0, hidden = 0.0, changedSide = 0.0;  // largest on-screen move, px
  double beyondTruth = 0.0;  // largest |search move − exact move| of a visible vertex, px
  std::size_t compared = 0;
};

PathJumps trackVirtualVertices(render::Renderer& renderer, double framesPerSecond, int frames,
                               const passes::ReflectionSettings& settings = virtualObjects()) {
  PathJumps jumps;
  std::vector<passes::ReflectedVertex> previous;
  std::map<std::size_t, glm::dvec2> previousExact;
  passes::FrameView previousView;
  for (int step = 0; step < frames; ++step) {
    const scene::ScenePose pose = scene::ScenePose::at(renderer.scene(), step / framesPerSecond);
    auto frame = renderer.render(pose, 640, 480, settings);
    EXPECT_TRUE(frame);
    if (!frame) return jumps;
    const auto current = renderer.readReflectedVertices();
    std::map<std::size_t, glm::dvec2> exact;
    for (const bench::MeasuredVertex& vertex : measureReflectionPoints(renderer, pose, *frame).vertices)
      exact[vertex.slot] = vertex.exact;
    for (std::size_t slot = 0; slot < previous.size(); ++slot) {
      const passes::ReflectedVertex &before = previous[slot], &now = current[slot];
      if (before.virtualPosition.w != 1.0f || now.virtualPosition.w != 1.0f) continue;  // unsolved
      const double move = glm::length(toPixels(frame->view, glm::vec3(now.virtualPosition), 640, 480) -
                                      toPixels(previousView, glm::vec3(before.virtualPosition), 640, 480));
      const bool wasHidden = before.state.w & passes::ReflectedVertex::kHidden;
      const bool isHidden = now.state.w & passes::ReflectedVertex::kHidden;
      double& largest = wasHidden != isHidden ? jumps.changedSide : isHidden ? jumps.hidden : jumps.visible;
      largest = std::max(largest, move);
      const auto exactNow = exact.find(slot), exactBefore = previousExact.find(slot);
      if (exactNow != exact.end() && exactBefore != previousExact.end())
        jumps.beyondTruth =
            std::max(jumps.beyondTruth, std::abs(move - glm::length(exactNow->second - exactBefore->second)));
      ++jumps.compared;
    }
    previous = current;
    previousExact = std::move(exact);
    previousView = frame->view;
  }
  return jumps;
}

}  // namespace

// The issue asks that no virtual vertex jump more than 2 px between frames along a smooth camera
// path. Visible vertices are held to their exact reflection's motion. Hidden ones (region C, off
// the mirror and clipped by its stencil) sit outside the silhouette, where the orbit moves them up
// to ~4.6 px a frame at 60 fps; that is motion, not a jump, if it shrinks with the frame interval:
// four times the frame rate must cut every largest move about four times (a discontinuity would not
// shrink at all) and bring it under 2 px.
TEST(ReflectionSearch, NoVirtualVertexJumpsAlongASmoothCameraPath) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const PathJumps at60 = trackVirtualVertices(*rig.renderer, 60.0, 12);
  rig.renderer->resetCoherence();
  const PathJumps at240 = trackVirtualVertices(*rig.renderer, 240.0, 48);
  ASSERT_GT(at60.compared, 2000u);
  EXPECT_GT(at60.visible, 0.5) << "the camera moved, so reflections must move";
  EXPECT_GT(at60.hidden, 0.5);
  EXPECT_GT(at60.changedSide, 0.1) << "the path must take vertices across the silhouette";
  // Measured: visible 1.87 px, 0.0001 px beyond the truth; hidden 4.57 → 0.97 px; changing side 1.61 → 0.40 px.
  EXPECT_LE(at60.visible, 2.0);
  EXPECT_LE(at60.beyondTruth, 0.05);
  EXPECT_LE(at240.beyondTruth, 0.05);
  for (const auto& [name, slow, fast] :
       {std::tuple{"visible", at60.visible, at240.visible}, std::tuple{"hidden", at60.hidden, at240.hidden},
        std::tuple{"changing side", at60.changedSide, at240.changedSide}}) {
    EXPECT_LE(fast, 2.0) << name;
    EXPECT_LE(fast, 0.35 * slow) << name << " vertices jump: their moves do not shrink with the frame interval";
  }
}

// Szabo reports jitter at grazing angles from his hierarchy: a vertex between cones is found by
// enlarged ones, which can lead to a neighbour of the right leaf, and that changes from frame to
// frame. Measured on the general path (the mesh sphere, no exact surface to refine on), where it would
// show: along the same orbit each search's visible vertices must follow the exact reflection's motion
// as closely as the other's.
TEST(ReflectionSearch, TheHierarchySearchFollowsTheExactMotionAsCloselyAsTheCrosshairSearch) {
  Rig rig = makeRig("mesh-sphere");
  ASSERT_TRUE(rig.renderer);
  std::map<passes::SearchStrategy, PathJumps> jumps;
  for (passes::SearchStrategy search : specula::testing::kSearchStrategies) {
    rig.renderer->resetCoherence();
    jumps[search] = trackVirtualVertices(*rig.renderer, 60.0, 12, withSearch(search));
    std::printf("%s on the mesh sphere: visible moves up to %.3f px, %.4f px beyond the exact motion\n",
                searchName(search).c_str(), jumps[search].visible, jumps[search].beyondTruth);
    ASSERT_GT(jumps[search].compared, 2000u);
  }
  const PathJumps& crosshair = jumps[passes::SearchStrategy::Crosshair];
  for (passes::SearchStrategy search : {passes::SearchStrategy::Hierarchy, passes::SearchStrategy::ExplosionMap}) {
    EXPECT_LE(jumps[search].beyondTruth, std::max(0.25, 1.5 * crosshair.beyondTruth)) << searchName(search);
    EXPECT_LE(jumps[search].visible, 1.5 * crosshair.visible)
        << searchName(search) << ": moves no larger than the crosshair search's";
  }
}

TEST(ReflectionSearch, CheckerSphereFrameAgreesWithTheRayTracedReference) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  auto frame = rig.renderer->render(pose, 320, 240, virtualObjects());
  ASSERT_TRUE(frame);
  auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(rig.renderer->scene()));
  ASSERT_TRUE(tracer) << tracer.error();
  auto truth = (*tracer)->render(pose, {320, 240, 1, 0});
  ASSERT_TRUE(truth) << truth.error();
  const reference::RgbaView ours{frame->rgba, 320, 240}, theirs{truth->rgba, 320, 240};
  auto mismatch = reference::maskedMismatch(ours, theirs, truth->mirrorMask);
  ASSERT_TRUE(mismatch);
  std::printf("checker-sphere searched: mirror mismatch %.5f, PSNR %.2f dB, SSIM %.4f\n", mismatch->share(),
              *reference::psnr(ours, theirs), *reference::ssim(ours, theirs));
  // Measured on llvmpipe with the default adaptive tessellation: 0.0036 / 39.0 dB / 0.9977 (the rest are
  // pixels on the reflected checker edges, where a virtual triangle's straight edge and the exact curve part).
  EXPECT_GT(mismatch->inside, 10000u);
  EXPECT_LE(mismatch->share(), 0.006);
  EXPECT_GE(*reference::psnr(ours, theirs), 37.0);
  EXPECT_GE(*reference::ssim(ours, theirs), 0.995);
  // Outside the mirror the two renderers agree to the byte (±1 for sRGB rounding), except where a
  // checker edge runs through a pixel's centre: there a last-bit difference in the floor's position
  // picks the other square (seen once at 320x240 on an H200; never on llvmpipe). Such a pixel has
  // our colour in a neighbour of the reference, and there may be only a handful.
  const auto sameColour = [&](std::size_t framePixel, std::size_t truthPixel) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(frame->rgba[framePixel * 4 + c] - truth->rgba[truthPixel * 4 + c]) > 1) return false;
    return true;
  };
  std::size_t outside = 0, onAnEdge = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 320 + static_cast<std::size_t>(x);
      if (truth->mirrorMask[i]) continue;
      ++outside;
      if (sameColour(i, i)) continue;
      bool neighbourHasIt = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (x + dx >= 0 && x + dx < 320 && y + dy >= 0 && y + dy < 240)
            neighbourHasIt = neighbourHasIt ||
                             sameColour(i, static_cast<std::size_t>(y + dy) * 320 + static_cast<std::size_t>(x + dx));
      ASSERT_TRUE(neighbourHasIt) << "pixel (" << x << ", " << y << ") outside the mirror differs from the reference";
      ++onAnEdge;
    }
  EXPECT_LE(onAnEdge, outside / 5000) << "pixels on a checker edge that took the other square";
}

TEST(ReflectionSearch, SeveralMovingMirrorsAreSearchedEveryFrame) {
  Rig rig = makeRig("ants");
  ASSERT_TRUE(rig.renderer);
  for (double t : {0.0, 0.25, 0.5}) {
    auto frame = rig.renderer->render(scene::ScenePose::at(rig.renderer->scene(), t), 320, 240, virtualObjects());
    ASSERT_TRUE(frame);
    EXPECT_GE(frame->drawnMirrors.size(), 2u);
    EXPECT_EQ(frame->search.unsolved, 0u);
    EXPECT_GT(frame->search.searched, 0u);
  }
}
