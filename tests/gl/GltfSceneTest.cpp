// A glTF file as a whole scene (issue #20): its metallic, smooth sphere becomes a mirror and matches
// the ray tracer, searched and as the planner renders it by default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "SceneRig.h"
#include "scene/GltfImporter.h"
#include "scene/builtin/BuiltinScenes.h"

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

// An animated file (issue #40): a bobbing chrome sphere reflects a box a turning node carries round it.
// At every sampled time, searched and ray cast, the frame matches the ray tracer posed at that time;
// and the reflection moves: the mirror's pixels differ from one time to the next.
TEST(GltfScene, AnimatedNodesReflectLikeTheRayTracerAtEveryTime) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / "animated.glb");
  ASSERT_TRUE(imported) << imported.error();
  const auto scene = std::make_shared<const scene::Scene>(std::move(imported->scene));
  ASSERT_TRUE(scene->moves());
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  passes::ReflectionSettings searched, cast;
  searched.rayCast = passes::RayCastRule::Never;
  cast.rayCast = passes::RayCastRule::Always;
  for (const passes::ReflectionSettings& settings : {searched, cast}) {
    std::vector<std::uint8_t> previous;
    for (double seconds : {0.25, 0.9, 1.6}) {
      const scene::ScenePose pose = scene::ScenePose::at(*scene, seconds);
      auto frame = rig.renderer->render(pose, 320, 240, settings);
      ASSERT_TRUE(frame) << frame.error();
      const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
      const char* method = settings.rayCast == passes::RayCastRule::Never ? "searched" : "ray cast";
      std::printf("%s at %.2f s: %zu mirror pixels, mismatch %.3f %%\n", method, seconds, mismatch.mirrorPixels,
                  100.0 * mismatch.share);
      EXPECT_GT(mismatch.mirrorPixels, 2800u) << method << " at " << seconds;  // measured 3160-3688
      EXPECT_LE(mismatch.share, 0.005) << method << " at " << seconds;         // measured 0.05-0.17 %
      EXPECT_NE(frame->rgba, previous) << method << " at " << seconds << ": the picture moved";
      previous = frame->rgba;
    }
  }
}

// Deforming objects (issue #40) before a chrome sphere: the GPU deforms their meshes every frame, the ray
// tracer poses them on the CPU through its own code. Searched and ray cast (whose hierarchy over a deforming
// mesh is refitted each frame), at every sampled time the mirror and the rest of the frame match, and the
// reflection follows the shape: the frame changes. The last time repeats the first: a shape drawn before
// leaves nothing behind.
void expectDeformingSceneMatchesTheRayTracer(const std::shared_ptr<const scene::Scene>& scene, std::size_t deforming) {
  const char* file = scene->name.c_str();
  ASSERT_EQ(scene->rig.morphed.size() + scene->rig.skinned.size(), deforming);
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  auto tracer = reference::RayTracer::create(scene);
  ASSERT_TRUE(tracer) << tracer.error();
  passes::ReflectionSettings searched, cast;
  searched.rayCast = passes::RayCastRule::Never;
  cast.rayCast = passes::RayCastRule::Always;
  for (const passes::ReflectionSettings& settings : {searched, cast}) {
    std::vector<std::uint8_t> previous;
    for (double seconds : {0.3, 1.0, 1.7, 0.3}) {
      const scene::ScenePose pose = scene::ScenePose::at(*scene, seconds);
      auto frame = rig.renderer->render(pose, 320, 240, settings);
      ASSERT_TRUE(frame) << frame.error();
      auto reference = (*tracer)->render(pose, specula::testing::tracedLike(*frame));
      ASSERT_TRUE(reference) << reference.error();
      const auto mismatch = specula::testing::mismatchAgainst(*reference, *frame);
      // The deforming objects as the camera sees them: every pixel that is not the mirror.
      std::vector<std::uint8_t> direct(reference->mirrorMask.size());
      for (std::size_t i = 0; i < direct.size(); ++i) direct[i] = reference->mirrorMask[i] == 0 ? 1 : 0;
      auto seen = reference::maskedMismatch({frame->rgba, frame->width, frame->height},
                                            {reference->rgba, frame->width, frame->height}, direct);
      ASSERT_TRUE(seen) << seen.error();
      const char* method = settings.rayCast == passes::RayCastRule::Never ? "searched" : "ray cast";
      std::printf("%s, %s at %.2f s: %zu mirror pixels, mismatch %.3f %%; elsewhere %.3f %%\n", file, method, seconds,
                  mismatch.mirrorPixels, 100.0 * mismatch.share, 100.0 * seen->share());
      EXPECT_GT(mismatch.mirrorPixels, 5000u) << method << " at " << seconds;  // measured 5391-5875
      EXPECT_LE(mismatch.share, 0.005) << method << " at " << seconds;         // measured 0.017-0.205 %
      // Measured 0.001 % at most; with the GPU's deformation left out, 2.9-9.9 %.
      EXPECT_LE(seen->share(), 0.0002) << method << " at " << seconds;
      EXPECT_NE(frame->rgba, previous) << method << " at " << seconds << ": the picture moved";
      previous = frame->rgba;
    }
  }
}

std::shared_ptr<const scene::Scene> importedTestFile(const char* file) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / file);
  EXPECT_TRUE(imported) << imported.error();
  return imported ? std::make_shared<const scene::Scene>(std::move(imported->scene)) : nullptr;
}

// A cloth waving and bulging behind the sphere and a box growing beside it, by morph target weights.
TEST(GltfScene, MorphingObjectsReflectLikeTheRayTracerAtEveryTime) {
  const auto scene = importedTestFile("morphing.glb");
  ASSERT_TRUE(scene);
  expectDeformingSceneMatchesTheRayTracer(scene, 2);
}

// An arm skinned to a shoulder and an elbow, swinging round beside the sphere and bending.
TEST(GltfScene, SkinnedObjectsReflectLikeTheRayTracerAtEveryTime) {
  const auto scene = importedTestFile("skinned.glb");
  ASSERT_TRUE(scene);
  expectDeformingSceneMatchesTheRayTracer(scene, 1);
}

// Mirrors that change shape: a chrome sphere squashed by a morph target and a chrome arm a skin bends. Their
// G-buffer is drawn from the deformed meshes and they are ray-cast whatever the settings ask (their parts'
// curvature was found at rest), against hierarchies refitted each frame, their own included.
TEST(GltfScene, DeformingMirrorsReflectLikeTheRayTracerAtEveryTime) {
  const auto scene = importedTestFile("deforming-mirrors.glb");
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->mirrorCount(), 2u);
  expectDeformingSceneMatchesTheRayTracer(scene, 2);
}

// The built-in deforming scene: a flag rippling behind a chrome ball (a mesh, so searched as meshes are).
TEST(GltfScene, TheBuiltInFlagReflectsLikeTheRayTracerAtEveryTime) {
  expectDeformingSceneMatchesTheRayTracer(std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("flag")), 1);
}

// Open chrome meshes (issue #40): a lidless bowl and a half-pipe panel are two-sided mirrors, ray-cast
// whatever the settings ask (a search needs a closed mesh), and match the ray tracer seen from either side.
TEST(GltfScene, OpenChromeMeshesAreTwoSidedMirrorsCastLikeTheRayTracer) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / "open-chrome.glb");
  ASSERT_TRUE(imported) << imported.error();
  ASSERT_EQ(imported->scene.mirrorCount(), 2u);
  for (const scene::SceneObject& object : imported->scene.objects) {
    if (object.mirror) {
      EXPECT_TRUE(object.mirror->twoSided()) << object.name;
    }
  }
  const auto scene = std::make_shared<const scene::Scene>(std::move(imported->scene));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  scene::ScenePose front = scene::ScenePose::at(*scene, 0.0);
  scene::ScenePose behind = front;  // the bowl's outside and the panel's inside face this eye
  behind.camera.eye = {0.0f, 3.2f, -7.0f};
  behind.camera.target = {0.0f, 0.8f, 0.0f};
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  for (const scene::ScenePose& pose : {front, behind}) {
    for (const passes::ReflectionSettings& settings : {passes::ReflectionSettings{}, searched}) {
      auto frame = rig.renderer->render(pose, 320, 240, settings);
      ASSERT_TRUE(frame) << frame.error();
      for (const render::MirrorPlanSummary& part : frame->plan)
        EXPECT_EQ(part.method, passes::PartMethod::RayCast) << "a two-sided mirror is cast, --ray-cast never too";
      const auto mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
      std::printf("eye z %.0f, %s: %zu mirror pixels, mismatch %.3f %%\n", pose.camera.eye.z,
                  settings.rayCast == passes::RayCastRule::Never ? "never" : "default", mismatch.mirrorPixels,
                  100.0 * mismatch.share);
      EXPECT_GT(mismatch.mirrorPixels, 3000u);
      EXPECT_LE(mismatch.share, 0.01);
    }
  }
}

// Seeking (issue #40): a searched frame at 1.3 s is the same whatever the renderer drew before it, the
// clip's earlier times or nothing at all (the search's frame-to-frame coherence changes only where it starts).
TEST(GltfScene, ASearchedFrameOfAnAnimationIsTheSameWhateverCameBefore) {
  auto imported = scene::importGltfScene(std::filesystem::path(SPECULA_TEST_DATA_DIR) / "gltf" / "animated.glb");
  ASSERT_TRUE(imported) << imported.error();
  const auto scene = std::make_shared<const scene::Scene>(std::move(imported->scene));
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  const scene::ScenePose target = scene::ScenePose::at(*scene, 1.3);
  specula::testing::Rig played = specula::testing::makeRig(scene);
  ASSERT_TRUE(played.renderer);
  for (double seconds : {0.2, 0.6, 1.0, 1.25})
    ASSERT_TRUE(played.renderer->render(scene::ScenePose::at(*scene, seconds), 320, 240, searched));
  auto afterPlaying = played.renderer->render(target, 320, 240, searched);
  specula::testing::Rig fresh = specula::testing::makeRig(scene);
  ASSERT_TRUE(fresh.renderer);
  auto sought = fresh.renderer->render(target, 320, 240, searched);
  ASSERT_TRUE(afterPlaying && sought);
  EXPECT_EQ(afterPlaying->rgba, sought->rgba);
}
