// Anti-aliasing (issue #20): a frame of N samples a pixel is the passes run at N sample points and
// averaged in linear light; the ray tracer takes the same points, so the two stay comparable.
#include <gtest/gtest.h>

#include <cstdio>

#include "SceneRig.h"
#include "gl/GlObject.h"
#include "scene/Primitives.h"
#include "scene/builtin/SceneAssembly.h"

using namespace specula;

namespace {

// A white unlit box on black: at one sample a pixel every pixel is exactly one of the two.
std::shared_ptr<const scene::Scene> whiteBoxOnBlack() {
  scene::Scene scene;
  scene.name = "white-box";
  const std::uint32_t box = scene::builtin::addMesh(scene, scene::primitives::box("box", glm::vec3(1.0f)));
  scene::builtin::addObject(scene, "box", box,
                            scene::builtin::addMaterial(scene, scene::builtin::emissive("white", 0xffffff)),
                            scene::builtin::placed(glm::vec3(0.0f), 20.0f));
  scene.camera = {{1.3f, 1.1f, 4.0f}, glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}, 40.0f};
  return std::make_shared<const scene::Scene>(std::move(scene));
}

std::size_t pixelsBetweenBlackAndWhite(const render::RenderedFrame& frame) {
  std::size_t between = 0;
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) between += frame.rgba[i] != 0 && frame.rgba[i] != 255 ? 1 : 0;
  return between;
}

}  // namespace

TEST(AntiAliasing, EdgesGetIntermediateValuesOnlyWithSamples) {
  const auto scene = whiteBoxOnBlack();
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto single = rig.renderer->render(pose, 320, 240, {}, 1);
  auto four = rig.renderer->render(pose, 320, 240, {}, 4);
  ASSERT_TRUE(single && four);
  EXPECT_EQ(pixelsBetweenBlackAndWhite(*single), 0u) << "one sample: every pixel is in or out";
  const std::size_t edge = pixelsBetweenBlackAndWhite(*four);
  std::printf("4 samples: %zu edge pixels between black and white\n", edge);
  EXPECT_GT(edge, 150u) << "the box's outline is some 300 pixels long";
  EXPECT_LT(edge, 3000u) << "only edges blend";
  // The ray tracer through the same sample points gives the same blends.
  auto tracer = reference::RayTracer::create(scene);
  ASSERT_TRUE(tracer) << tracer.error();
  auto truth = (*tracer)->render(pose, specula::testing::tracedLike(*four));
  ASSERT_TRUE(truth) << truth.error();
  int worst = 0;
  std::size_t off = 0;
  for (std::size_t i = 0; i < four->rgba.size(); i += 4) {
    const int difference = std::abs(int(four->rgba[i]) - int(truth->rgba[i]));
    worst = std::max(worst, difference);
    off += difference > 2 ? 1 : 0;
  }
  std::printf("against the 4-ray reference: %zu pixels differ by more than 2, at most %d\n", off, worst);
  EXPECT_LE(off, 4u) << "a sample exactly on an edge may fall either way";
}

// Mirrors too: the reflection is drawn once per sample point, on the general (mesh) path and the planner's.
TEST(AntiAliasing, MirrorFramesMatchTheRayTracerAtTheSameSamples) {
  for (const char* name : {"checker-sphere", "mesh-sphere"}) {
    specula::testing::Rig rig = specula::testing::makeRig(name);
    ASSERT_TRUE(rig.renderer);
    const auto scene = std::make_shared<const scene::Scene>(rig.renderer->scene());
    const scene::ScenePose pose = scene::ScenePose::at(*scene, 2.0);
    passes::ReflectionSettings searched;
    searched.rayCast = passes::RayCastRule::Never;
    for (const passes::ReflectionSettings& settings : {passes::ReflectionSettings{}, searched}) {
      auto frame = rig.renderer->render(pose, 320, 240, settings, 4);
      ASSERT_TRUE(frame) << frame.error();
      EXPECT_EQ(frame->samples, 4);
      const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
      std::printf("%s %s: mirror mismatch %.3f %% of %zu px\n", name,
                  settings.rayCast == passes::RayCastRule::Never ? "searched" : "default", 100.0 * mismatch.share,
                  mismatch.mirrorPixels);
      EXPECT_GT(mismatch.mirrorPixels, 2000u);
      EXPECT_LE(mismatch.share, 0.01) << name;
    }
  }
}

TEST(AntiAliasing, FramesOfOneSizeCreateNoGlObjectsAndReportEachPassOnce) {
  specula::testing::Rig rig = specula::testing::makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  const scene::Scene& scene = rig.renderer->scene();
  ASSERT_TRUE(rig.renderer->render(scene::ScenePose::at(scene, 0.0), 320, 240, {}, 4));
  const std::uint64_t before = gl::glObjectsCreated.load();
  auto frame = rig.renderer->render(scene::ScenePose::at(scene, 0.5), 320, 240, {}, 8);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_EQ(gl::glObjectsCreated.load(), before) << "the sum is kept with the frame's size";
  std::vector<std::string> names;
  for (const render::StageTiming& stage : frame->timings.stages) names.push_back(stage.name);
  EXPECT_EQ(std::count(names.begin(), names.end(), "scene"), 1);
  EXPECT_EQ(std::count(names.begin(), names.end(), "anti-aliasing"), 1);
  EXPECT_EQ(names.back(), "readback");
  EXPECT_FALSE(rig.renderer->render(scene::ScenePose::at(scene, 0.5), 320, 240, {}, 3)) << "3 is no sample count";
}
