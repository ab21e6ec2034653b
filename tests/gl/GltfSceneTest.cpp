// A glTF file as a whole scene (issue #20): its metallic, smooth sphere becomes a mirror and matches
// the ray tracer, searched and as the planner renders it by default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "SceneRig.h"
#include "scene/GltfImporter.h"

using namespace specula;

TEST(GltfScene, ChromeSphereFromAGlbReflectsLikeTheRayTracer) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / "chrome-sphere.glb");
  ASSERT_TRUE(imported) << imported.error();
  EXPECT_EQ(imported->scene.mirrorCount(), 1u);
  const auto scene = std::make_shared<const scene::Scene>(std::move(imported->scene));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  for (const passes::ReflectionSettings& settings : {passes::ReflectionSettings{}, searched}) {
    auto frame = rig.renderer->render(pose, 320, 240, settings);
    ASSERT_TRUE(frame) << frame.error();
    const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
    std::printf("%s: %zu mirror pixels, mismatch %.3f %%\n",
                settings.rayCast == passes::RayCastRule::Never ? "searched" : "default", mismatch.mirrorPixels,
                100.0 * mismatch.share);
    EXPECT_GT(mismatch.mirrorPixels, 3000u) << "the sphere fills a good part of the frame";
    EXPECT_LE(mismatch.share, 0.01);
  }
}

// A multi-part model as a user opens it: no camera (the view frames it), six chrome parts.
TEST(GltfScene, MultiPartEngineMatchesTheRayTracer) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / "engine.glb");
  ASSERT_TRUE(imported) << imported.error();
  const auto scene = std::make_shared<const scene::Scene>(std::move(imported->scene));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto frame = rig.renderer->render(pose, 320, 240, {}, 4);
  ASSERT_TRUE(frame) << frame.error();
  const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
  std::printf("engine: %zu mirror pixels, mismatch %.3f %%\n", mismatch.mirrorPixels, 100.0 * mismatch.share);
  EXPECT_GT(mismatch.mirrorPixels, 500u);
  EXPECT_LE(mismatch.share, 0.01);
}
