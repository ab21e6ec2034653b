// A ray-cast part casts each object only on the 8×8 tiles whose rays may reach the object's bounding
// sphere (shaders/virtual-objects/ray-cast-tiles.comp), nearest objects first so that their hits cut
// the later objects' traversals. Both are pure savings: the picture must be the one every object cast
// over every pixel gives, on analytic and mesh mirrors, convex and concave parts, many tiny mirrors.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "SceneRig.h"

using namespace specula;

namespace {

constexpr int kWidth = 480, kHeight = 360;

std::size_t differingPixels(const render::RenderedFrame& a, const render::RenderedFrame& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c)
      if (std::abs(a.rgba[i + c] - b.rgba[i + c]) > 2) {
        ++differing;
        break;
      }
  return differing;
}

passes::CastTileCount castTiles(const render::RenderedFrame& frame) {
  passes::CastTileCount total;
  for (const render::MirrorPlanSummary& part : frame.plan) {
    total.listed += part.castTiles.listed;
    total.possible += part.castTiles.possible;
  }
  return total;
}

}  // namespace

// ufo: 39 objects around a saucer; teapot-table: five objects in a mirror ball; kitchen: a mesh bowl,
// convex outside and concave inside that sees itself; beads: 29 mirrors of a few pixels each.
TEST(RayCastTiles, EachObjectIsCastOnlyOnTilesItCanReachAndThePictureStays) {
  for (const auto& [name, time] : {std::pair{"ufo", 0.0}, std::pair{"ufo", 7.0}, std::pair{"teapot-table", 1.0},
                                   std::pair{"kitchen", 1.0}, std::pair{"beads", 0.5}}) {
    const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(name));
    specula::testing::Rig rig = specula::testing::makeRig(scene);
    ASSERT_TRUE(rig.renderer);
    const scene::ScenePose pose = scene::ScenePose::at(*scene, time);
    passes::ReflectionSettings settings;
    settings.rayCast = passes::RayCastRule::Always;
    auto tiled = rig.renderer->render(pose, kWidth, kHeight, settings);
    ASSERT_TRUE(tiled) << tiled.error();
    settings.castTiles = false;
    auto everywhere = rig.renderer->render(pose, kWidth, kHeight, settings);
    ASSERT_TRUE(everywhere) << everywhere.error();

    const passes::CastTileCount withTiles = castTiles(*tiled), without = castTiles(*everywhere);
    std::printf("%s at t = %.1f: cast on %zu of %zu object tiles\n", name, time, withTiles.listed, withTiles.possible);
    ASSERT_GT(withTiles.possible, 0u) << name << ": some part is ray-cast";
    EXPECT_EQ(withTiles.possible, without.possible) << name;
    EXPECT_EQ(without.listed, without.possible) << name << ": untiled, every object covers every tile";
    EXPECT_LT(withTiles.listed, withTiles.possible) << name << ": the classification leaves tiles out";
    EXPECT_EQ(differingPixels(*tiled, *everywhere), 0u) << name << " at t = " << time;
  }
}

// The saucer's 39 objects each appear on a small share of it: at most a fifth of the object tiles are
// cast, and the frame still matches the ray tracer.
TEST(RayCastTiles, TheUfoCastsAFractionOfItsObjectTilesAndMatchesTheRayTracer) {
  const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("ufo"));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto frame = rig.renderer->render(pose, kWidth, kHeight);
  ASSERT_TRUE(frame) << frame.error();
  ASSERT_EQ(frame->plan.size(), 1u);
  EXPECT_EQ(frame->plan[0].method, passes::PartMethod::RayCast);
  const passes::CastTileCount tiles = castTiles(*frame);
  EXPECT_LE(5 * tiles.listed, tiles.possible) << tiles.listed << " of " << tiles.possible;
  const double mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame).share;
  std::printf("ufo: %.2f %% of the mirror pixels differ from the ray tracer\n", 100.0 * mismatch);
  EXPECT_LE(mismatch, 0.005);
}
