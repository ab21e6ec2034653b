// The live accuracy estimate on real frames: for methods whose full-frame mirror mismatch against the
// ray tracer ranges from none to most of the mirror, the estimate's 95 % interval (from 256 sampled
// pixels, reference::sampleMirrorMismatch) must contain the full comparison's figure in ≥ 90 % of frames.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "SceneRig.h"
#include "reference/MismatchSample.h"
#include "reference/PixelTracer.h"
#include "reference/RayTracer.h"
#include "scene/ScenePose.h"

namespace specula::testing {
namespace {

constexpr int kWidth = 320, kHeight = 240, kFrames = 8;

struct Case {
  const char* name;
  const char* scene;
  passes::ReflectionSettings settings;
  float approach;  // the camera's distance to its target, as a share of the scene camera's
};

std::vector<Case> cases() {
  passes::ReflectionSettings environmentMap;
  environmentMap.method = passes::ReflectionMethod::EnvironmentMap;
  passes::ReflectionSettings bareExplosionMap = virtualObjects();
  bareExplosionMap.search = passes::SearchStrategy::ExplosionMap;
  passes::ReflectionSettings untessellated = virtualObjects();
  untessellated.tessellation.mode = passes::TessellationMode::None;
  passes::ReflectionSettings rayCast;
  rayCast.rayCast = passes::RayCastRule::Always;
  return {{"environment map up close", "checker-sphere", environmentMap, 0.6f},
          {"bare explosion map", "mesh-sphere", bareExplosionMap, 1.0f},
          {"tessellation off", "teapot-table", untessellated, 1.0f},
          {"searched", "checker-sphere", virtualObjects(), 1.0f},
          {"ray cast (exact)", "mesh-sphere", rayCast, 1.0f}};
}

TEST(LiveAccuracyCalibration, TheIntervalContainsTheFullFrameMismatchInNineFramesOfTen) {
  int frames = 0, covered = 0;
  for (const Case& c : cases()) {
    auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(c.scene));
    Rig rig = makeRig(scene);
    ASSERT_TRUE(rig.renderer);
    auto tracer = reference::RayTracer::create(scene);
    ASSERT_TRUE(tracer) << tracer.error();
    double worstTruth = 0.0, bestTruth = 1.0;
    for (int i = 0; i < kFrames; ++i) {
      scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
      const glm::vec3 offset = c.approach * (pose.camera.eye - pose.camera.target);
      const glm::mat4 swing = glm::rotate(glm::mat4(1.0f), glm::radians(9.0f * static_cast<float>(i)), {0, 1, 0});
      pose.camera.eye = pose.camera.target + glm::vec3(swing * glm::vec4(offset, 0.0f));
      auto frame = rig.renderer->render(pose, kWidth, kHeight, c.settings);
      ASSERT_TRUE(frame) << frame.error();
      auto exact = (*tracer)->render(pose, tracedLike(*frame));
      ASSERT_TRUE(exact) << exact.error();
      const double truth = mismatchAgainst(*exact, *frame).share;
      auto pixels = (*tracer)->pixelTracer(*(*tracer)->posedScene(pose), pose.camera, tracedLike(*frame));
      ASSERT_TRUE(pixels) << pixels.error();
      reference::MismatchSampleOptions options;
      options.seed = static_cast<std::uint64_t>(i);
      auto sample = reference::sampleMirrorMismatch(**pixels, {frame->rgba, kWidth, kHeight}, options);
      ASSERT_TRUE(sample) << sample.error();
      const reference::ShareEstimate& e = sample->mismatch;
      const bool inside = e.low <= truth && truth <= e.high;
      std::printf("%-26s frame %d: full %.4f, estimate %.4f [%.4f, %.4f]%s\n", c.name, i, truth, e.share(), e.low,
                  e.high, inside ? "" : "  MISSED");
      ++frames;
      covered += inside ? 1 : 0;
      worstTruth = std::max(worstTruth, truth);
      bestTruth = std::min(bestTruth, truth);
      EXPECT_EQ(e.sampled, 256u) << c.name << ": the mirror fills enough of every frame";
    }
    if (std::string(c.name) == "ray cast (exact)") {
      EXPECT_LT(worstTruth, 0.001) << "an exact method";
    }
    if (std::string(c.name) == "environment map up close") {
      EXPECT_GT(bestTruth, 0.1) << "a method that is off";
    }
  }
  std::printf("interval contained the full-frame mismatch in %d of %d frames\n", covered, frames);
  EXPECT_GE(covered, (9 * frames + 9) / 10);
}

}  // namespace
}  // namespace specula::testing
