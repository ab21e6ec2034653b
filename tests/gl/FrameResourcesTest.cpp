// What a frame costs besides its work: GL objects created per frame, honest per-pass times, and
// search state kept per session when one renderer serves several.
#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "gl/GlContext.h"
#include "gl/GlObject.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "session/GlFrameRenderer.h"
#include "SceneRig.h"

using namespace specula;
using specula::testing::makeRig;
using specula::testing::Rig;

TEST(FrameResources, FramesOfOneSizeCreateNoGlObjects) {
  // The kitchen: a mirror of two parts that sees itself, searched and tessellated, or (the planner's
  // choice at this size) ray-cast against every object's hierarchy; the Utah teapot: a parametric
  // mirror of six parts, whose G-buffer layers are copied from scratch textures.
  struct Case {
    const char* scene;
    passes::ReflectionSettings settings;
  };
  for (const auto& [sceneName, settings] :
       {Case{"kitchen", specula::testing::virtualObjects()}, Case{"kitchen", {}}, Case{"utah-teapot", {}}}) {
    SCOPED_TRACE(std::string(sceneName) + (settings.rayCast == passes::RayCastRule::Never ? " searched" : " planned"));
    Rig rig = makeRig(sceneName);
    ASSERT_TRUE(rig.renderer);
    const scene::Scene& scene = rig.renderer->scene();
    for (int i = 0; i < 2; ++i)
      ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 0.1 * i), 320, 240, settings));
    const std::uint64_t before = gl::glObjectsCreated.load();
    for (int i = 2; i < 6; ++i)
      ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 0.1 * i), 320, 240, settings));
    EXPECT_EQ(gl::glObjectsCreated.load(), before) << "render targets, buffers and queries are kept between frames";
    ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 1.0), 256, 192, settings));
    EXPECT_GT(gl::glObjectsCreated.load(), before) << "a new size needs new targets";
    const std::uint64_t resized = gl::glObjectsCreated.load();
    ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 1.1), 256, 192, settings));
    EXPECT_EQ(gl::glObjectsCreated.load(), resized);
  }
}

// On a CPU rasterizer a pass's draws run when a later command flushes them; timed by the wall clock
// after each pass has finished, the passes account for the frame and each for its own work.
TEST(FrameResources, PassTimesAccountForTheFrame) {
  Rig rig = makeRig("teapot-table");
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  passes::ReflectionSettings searched;  // every reflection pass runs
  searched.rayCast = passes::RayCastRule::Never;
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240, searched));  // shaders compiled, targets sized
  auto frame = rig.renderer->render(pose, 320, 240, searched);
  ASSERT_TRUE(frame) << frame.error();
  const auto& stages = frame->timings.stages;
  ASSERT_GE(stages.size(), 6u);
  EXPECT_EQ(stages.front().name, "scene");
  double sum = 0.0;
  for (const render::StageTiming& stage : stages) {
    EXPECT_GE(stage.milliseconds, 0.0) << stage.name;
    sum += stage.milliseconds;
  }
  EXPECT_LE(sum, frame->timings.totalMilliseconds * 1.001);
  if (rig.context->info().renderer.find("llvmpipe") != std::string::npos) {
    EXPECT_GE(sum, 0.8 * frame->timings.totalMilliseconds) << "the passes account for the frame";
    EXPECT_GT(stages.front().milliseconds, 0.05 * sum)
        << "the scene pass's raster work is its own, not the next pass's";
  }
}

TEST(FrameResources, EachSessionResumesItsOwnSearchStateAfterAnotherRendered) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  ASSERT_TRUE(context) << context.error();
  auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("checker-sphere"));
  auto renderer = session::GlFrameRenderer::create(std::move(*context), scene);
  ASSERT_TRUE(renderer) << renderer.error();
  passes::ReflectionSettings searched;  // the planner would ray-cast the sphere, cheaper on llvmpipe
  searched.rayCast = passes::RayCastRule::Never;
  session::RenderJob a{1, scene::ScenePose::at(*scene, 0.0), 320, 240, searched};
  session::RenderJob b{2, scene::ScenePose::at(*scene, 9.0), 320, 240, searched};  // the camera orbits 180° away
  const auto render = [&](const session::RenderJob& job) {
    auto out = (*renderer)->render(job);
    EXPECT_TRUE(out) << out.error();
    return out ? out->search : v1::SearchStatistics{};
  };
  const v1::SearchStatistics first = render(a);
  EXPECT_EQ(first.cold_starts(), first.searched()) << "a new session starts cold";
  const v1::SearchStatistics warm = render(a);
  EXPECT_EQ(warm.cold_starts(), 0u);
  const v1::SearchStatistics other = render(b);
  EXPECT_EQ(other.cold_starts(), other.searched()) << "another session does not inherit session 1's texels";
  const v1::SearchStatistics back = render(a);
  EXPECT_EQ(back.cold_starts(), 0u) << "session 1 resumes from its own last texels";
  EXPECT_NEAR(back.mean_steps(), warm.mean_steps(), 0.01);
  EXPECT_LT(back.mean_steps(), 0.5 * first.mean_steps());
}
