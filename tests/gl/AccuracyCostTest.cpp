// The methods `specula bench accuracy` weighs, against the ray tracer: the environment-map baseline
// is right only for distant surroundings, and the search does not flicker along a smooth path.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/ImageComparison.h"
#include "gl/GlContext.h"
#include "reference/ImageMetrics.h"
#include "reference/RayTracer.h"
#include "SceneRig.h"
#include "render/Renderer.h"
#include "scene/Primitives.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::testing {
namespace {

using namespace scene::builtin;

std::unique_ptr<gl::GlContext> context() {
  auto created = gl::GlContext::create(gl::PlatformChoice::Auto);
  EXPECT_TRUE(created) << created.error();
  return created ? std::move(*created) : nullptr;
}

// A unit mirror sphere among five coloured balls `distance` away on the axes (none between it and
// the camera): the environment map's assumption, everything infinitely far, holds better the
// larger `distance` is.
std::shared_ptr<const scene::Scene> sphereAmongBalls(float distance) {
  scene::Scene scene;
  scene.name = "sphere-among-balls";
  scene.background = glm::vec3(0.02f, 0.03f, 0.05f);
  scene.lights.push_back(sunLight({1.0f, 2.0f, 1.5f}, 1.0f));
  const std::uint32_t sphere =
      addSphereMirror(scene, "mirror", addMesh(scene, scene::primitives::uvSphere("mirror", 1.0f, 96, 48)),
                      addMaterial(scene, perfectMirror("mirror")), 1.0f, placed(glm::vec3(0.0f)));
  scene.objects[sphere].reflected = false;
  const std::uint32_t ball = addMesh(scene, scene::primitives::uvSphere("ball", 0.4f * distance, 48, 24));
  const std::pair<glm::vec3, std::uint32_t> balls[] = {{{1, 0, 0}, 0xd62728},
                                                       {{-1, 0, 0}, 0x2ca02c},
                                                       {{0, 1, 0}, 0x1f77b4},
                                                       {{0, -1, 0}, 0xff7f0e},
                                                       {{0, 0, -1}, 0xe0e0e0}};
  for (const auto& [direction, colour] : balls)
    addObject(scene, "ball", ball, addMaterial(scene, matte("ball", colour)), placed(direction * distance));
  scene.camera = {{0.6f, 0.8f, 4.0f}, glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}, 40.0f};
  return std::make_shared<const scene::Scene>(std::move(scene));
}

// Mirror mismatch of one frame against the ray tracer.
double mirrorMismatch(gl::GlContext& gl, std::shared_ptr<const scene::Scene> scene,
                      const passes::ReflectionSettings& settings) {
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto tracer = reference::RayTracer::create(scene);
  EXPECT_TRUE(tracer) << tracer.error();
  auto truth = (*tracer)->render(pose, {320, 240, 1, 0});
  EXPECT_TRUE(truth) << truth.error();
  auto renderer = render::Renderer::create(gl, scene);
  EXPECT_TRUE(renderer) << renderer.error();
  auto frame = (*renderer)->render(pose, 320, 240, specula::testing::virtualObjects(settings));
  EXPECT_TRUE(frame) << frame.error();
  auto comparison = bench::compareWithReference(*frame, *truth);
  EXPECT_TRUE(comparison) << comparison.error();
  return comparison ? comparison->mirrorMismatch : 1.0;
}

passes::ReflectionSettings environmentMap() {
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::EnvironmentMap;
  return settings;
}

TEST(EnvironmentMap, MatchesTheRayTracerForDistantSurroundingsAndLosesToTheSearchNearby) {
  auto gl = context();
  ASSERT_TRUE(gl);
  const double far = mirrorMismatch(*gl, sphereAmongBalls(200.0f), environmentMap());
  const double near = mirrorMismatch(*gl, sphereAmongBalls(3.0f), environmentMap());
  std::printf("environment map mirror mismatch: surroundings at 200 radii %.4f, at 3 radii %.4f\n", far, near);
  EXPECT_LT(far, 0.02) << "from 200 radii the mirror's centre sees what every point of it sees";
  EXPECT_GT(near, 2.0 * far) << "near objects show the parallax a single cube map cannot have";

  // Checker-sphere's floor touches the mirror: the baseline is off, the virtual objects are not.
  auto checker = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("checker-sphere"));
  const double baseline = mirrorMismatch(*gl, checker, environmentMap());
  const double search = mirrorMismatch(*gl, checker, {});
  std::printf("checker-sphere mirror mismatch: environment map %.4f, search %.4f\n", baseline, search);
  EXPECT_GT(baseline, 3.0 * search);
  EXPECT_LT(search, 0.05);
}

TEST(EnvironmentMap, AMirrorOffScreenRendersWithoutAnEnvironmentPass) {
  auto gl = context();
  ASSERT_TRUE(gl);
  auto scene = sphereAmongBalls(10.0f);
  auto renderer = render::Renderer::create(*gl, scene);
  ASSERT_TRUE(renderer) << renderer.error();
  scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  pose.camera.target = pose.camera.eye + glm::vec3(0.0f, 0.0f, 1.0f);  // looking away from the mirror
  auto frame = (*renderer)->render(pose, 160, 120, environmentMap());
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_TRUE(frame->drawnMirrors.empty());
  for (const render::StageTiming& stage : frame->timings.stages) EXPECT_NE(stage.name, "environment-map");
}

// Flicker is change the truth does not have: along a smooth orbit, the share of mirror pixels that
// change strongly from one frame to the next must track the ray tracer's own frame-to-frame change.
TEST(TemporalStability, PerFrameImageChangeInsideTheMirrorTracksTheRayTracer) {
  auto gl = context();
  ASSERT_TRUE(gl);
  auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("checker-sphere"));
  auto tracer = reference::RayTracer::create(scene);
  ASSERT_TRUE(tracer) << tracer.error();
  auto renderer = render::Renderer::create(*gl, scene);
  ASSERT_TRUE(renderer) << renderer.error();
  constexpr int kWidth = 320, kHeight = 240, kFrames = 10;
  constexpr float kDegreesPerFrame = 0.5f;  // a 30 °/s orbit at 60 frames per second
  std::vector<std::uint8_t> lastOurs, lastTruth;
  double worstExcess = 0.0;
  for (int i = 0; i < kFrames; ++i) {
    scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
    const glm::mat4 swing =
        glm::rotate(glm::mat4(1.0f), glm::radians(kDegreesPerFrame * static_cast<float>(i)), glm::vec3(0, 1, 0));
    pose.camera.eye = pose.camera.target + glm::vec3(swing * glm::vec4(pose.camera.eye - pose.camera.target, 0.0f));
    auto truth = (*tracer)->render(pose, {kWidth, kHeight, 1, 0});
    ASSERT_TRUE(truth) << truth.error();
    auto ours = (*renderer)->render(pose, kWidth, kHeight, specula::testing::virtualObjects());
    ASSERT_TRUE(ours) << ours.error();
    if (i > 0) {
      const auto change = [&](const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& now) {
        auto mismatch = reference::maskedMismatch({before, kWidth, kHeight}, {now, kWidth, kHeight}, truth->mirrorMask);
        EXPECT_TRUE(mismatch) << mismatch.error();
        return mismatch ? mismatch->share() : 1.0;
      };
      const double oursChange = change(lastOurs, ours->rgba), truthChange = change(lastTruth, truth->rgba);
      std::printf("frame %d: mirror pixels changed %.4f (ray tracer %.4f)\n", i, oursChange, truthChange);
      EXPECT_GT(truthChange, 0.0) << "the orbit moves the reflection";
      worstExcess = std::max(worstExcess, oursChange - truthChange);
    }
    lastOurs = std::move(ours->rgba);
    lastTruth = std::move(truth->rgba);
  }
  EXPECT_LE(worstExcess, 0.01) << "more mirror pixels change per frame than in the ray-traced truth: flicker";
}

}  // namespace
}  // namespace specula::testing
