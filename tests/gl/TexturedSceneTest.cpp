// Textures (issue #20): textured objects seen directly and in a mesh mirror match the ray tracer,
// which samples the same mip levels over the same footprints; from a JSON scene and from glTF.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "SceneRig.h"
#include "scene/GltfImporter.h"
#include "scene/SceneLoader.h"

using namespace specula;

namespace {

const std::filesystem::path kData(SPECULA_TEST_DATA_DIR);

// Share of all pixels (not only the mirror's) that differ strongly from the ray tracer's.
double wholeFrameMismatch(const std::shared_ptr<const scene::Scene>& scene, const scene::ScenePose& pose,
                          const render::RenderedFrame& frame) {
  auto tracer = reference::RayTracer::create(scene);
  EXPECT_TRUE(tracer) << tracer.error();
  auto truth = (*tracer)->render(pose, specula::testing::tracedLike(frame));
  EXPECT_TRUE(truth) << truth.error();
  const std::vector<std::uint8_t> everywhere(
      static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 1);
  auto mismatch = reference::maskedMismatch({frame.rgba, frame.width, frame.height},
                                            {truth->rgba, frame.width, frame.height}, everywhere);
  EXPECT_TRUE(mismatch) << mismatch.error();
  return mismatch ? mismatch->share() : 1.0;
}

void expectLikeTheRayTracer(const std::shared_ptr<const scene::Scene>& scene, double frameBound, double mirrorBound) {
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  for (const passes::ReflectionSettings& settings : {passes::ReflectionSettings{}, searched})
    for (int samples : {1, 4}) {
      const char* how = settings.rayCast == passes::RayCastRule::Never ? "searched" : "default";
      SCOPED_TRACE(std::string(how) + ", " + std::to_string(samples) + " samples");
      auto frame = rig.renderer->render(pose, 320, 240, settings, samples);
      ASSERT_TRUE(frame) << frame.error();
      const double whole = wholeFrameMismatch(scene, pose, *frame);
      const auto mirror = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame);
      std::printf("%s, %d samples: frame mismatch %.3f %%, mirror %.3f %% of %zu px\n", how, samples, 100.0 * whole,
                  100.0 * mirror.share, mirror.mirrorPixels);
      EXPECT_LE(whole, frameBound);
      EXPECT_LE(mirror.share, mirrorBound);
    }
}

}  // namespace

// A tiled floor and a clamped crate, reflected in a mesh sphere (no analytic shape: the general path).
TEST(TexturedScene, JsonSceneTexturesMatchTheRayTracerDirectlyAndInAMeshMirror) {
  auto loaded = scene::loadSceneFile(kData / "scenes" / "good" / "textured.json");
  ASSERT_TRUE(loaded) << loaded.error();
  ASSERT_EQ(loaded->textures.size(), 2u) << "one image, two wrap modes";
  ASSERT_FALSE(loaded->objects[0].mirror->analytic.has_value());
  expectLikeTheRayTracer(std::make_shared<const scene::Scene>(std::move(loaded.value())), 0.01, 0.02);
}

TEST(TexturedScene, GltfTexturesMatchTheRayTracer) {
  auto imported = scene::importGltfScene(kData / "gltf" / "textured-box.gltf");
  ASSERT_TRUE(imported) << imported.error();
  expectLikeTheRayTracer(std::make_shared<const scene::Scene>(std::move(imported->scene)), 0.01, 0.0);
}

// The textured floor changes the picture: drawn without its texture the frame would differ (the test
// above could not pass with textures ignored on both sides).
TEST(TexturedScene, TheTextureShows) {
  auto loaded = scene::loadSceneFile(kData / "scenes" / "good" / "textured.json");
  ASSERT_TRUE(loaded) << loaded.error();
  scene::Scene plain = *loaded;
  for (scene::Material& material : plain.materials) material.texture.reset();
  const auto textured = std::make_shared<const scene::Scene>(std::move(loaded.value()));
  specula::testing::Rig rig = specula::testing::makeRig(std::make_shared<const scene::Scene>(std::move(plain)));
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*textured, 0.0);
  auto frame = rig.renderer->render(pose, 320, 240);
  ASSERT_TRUE(frame) << frame.error();
  EXPECT_GT(wholeFrameMismatch(textured, pose, *frame), 0.3) << "most of the frame is textured floor";
}

// Two textured glTF groups and a chrome one placed by a scene file (one scaled and turned), as the ray tracer sees
// them.
TEST(TexturedScene, IncludedGltfGroupsMatchTheRayTracer) {
  auto loaded = scene::loadSceneFile(kData / "gltf" / "includes.json");
  ASSERT_TRUE(loaded) << loaded.error();
  expectLikeTheRayTracer(std::make_shared<const scene::Scene>(std::move(loaded.value())), 0.01, 0.01);
}
