// The frame plan leaves out what a mirror cannot show (passes/FramePlan, passes/MirrorReach): an
// object in a closed convex mirror's shadow, objects behind a flat part, every object of a part that
// faces away. Left out means fewer searches and the same picture as `--plan everything`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "gl/GlContext.h"
#include "render/Renderer.h"
#include "scene/SceneLoader.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "SceneRig.h"

using namespace specula;

namespace {

constexpr int kWidth = 480, kHeight = 360;

std::shared_ptr<const scene::Scene> parse(const std::string& json) {
  auto scene = scene::parseScene(json, ".", "test scene");
  EXPECT_TRUE(scene) << scene.error();
  return scene ? std::make_shared<const scene::Scene>(std::move(*scene)) : nullptr;
}

struct PlannedAndEverything {
  render::RenderedFrame needed, everything;
  std::size_t differingPixels = 0;  // pixels where the two frames differ by more than 2 levels
};

// The same pose rendered with the planner and without, each from cold seeds.
PlannedAndEverything renderBoth(const std::shared_ptr<const scene::Scene>& scene,
                                passes::ReflectionSettings settings = {}, glm::ivec2 size = {kWidth, kHeight}) {
  PlannedAndEverything result;
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  if (!rig.renderer) return result;
  render::Renderer* renderer = rig.renderer.get();
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  for (auto [scope, frame] :
       {std::pair{passes::PlanScope::Needed, &result.needed}, {passes::PlanScope::Everything, &result.everything}}) {
    settings.plan = scope;
    settings.rayCast = passes::RayCastRule::Never;  // the planner's cuts are what is compared: both frames search
    renderer->resetCoherence();
    auto rendered = renderer->render(pose, size.x, size.y, settings);
    EXPECT_TRUE(rendered) << rendered.error();
    if (!rendered) return result;
    *frame = std::move(*rendered);
  }
  for (std::size_t i = 0; i < result.needed.rgba.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c)
      if (std::abs(result.needed.rgba[i + c] - result.everything.rgba[i + c]) > 2) {
        ++result.differingPixels;
        break;
      }
  return result;
}

// The scene at t = 0 with default settings (the planner's own choices), and how it compares with the
// ray tracer's image.
struct DefaultFrame {
  render::RenderedFrame frame;
  specula::testing::MirrorMismatch mismatch;
};
DefaultFrame defaultFrameAgainstRayTracer(const std::shared_ptr<const scene::Scene>& scene) {
  DefaultFrame result;
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  if (!rig.renderer) return result;
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  auto rendered = rig.renderer->render(pose, kWidth, kHeight);
  EXPECT_TRUE(rendered) << rendered.error();
  if (!rendered) return result;
  result.frame = std::move(*rendered);
  result.mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, result.frame);
  return result;
}

std::size_t culledVertices(const render::RenderedFrame& frame) {
  std::size_t culled = 0;
  for (const render::MirrorPlanSummary& mirror : frame.plan) culled += mirror.culledVertices;
  return culled;
}

// checker-sphere with a red ball of 2 145 vertices hidden behind the mirror from the camera and a
// second one beside it, reflected; `mirror` is the mirror's JSON (analytic sphere or mesh).
std::string sphereWithAHiddenBall(const std::string& mirror) {
  return R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#000000",
    "camera": {"eye": [1, 3, 3.5], "target": [0, -0.3, 0], "fov": 40},
    "meshes": [{"name": "mirror-sphere", "primitive": {"type": "sphere", "radius": 1, "slices": 128, "stacks": 64}},
      {"name": "floor", "primitive": {"type": "grid", "size": [16, 16], "cells": [16, 16]}},
      {"name": "ball", "primitive": {"type": "sphere", "radius": 0.2, "slices": 64, "stacks": 32}}],
    "materials": [{"name": "mirror", "color": "#000000", "reflectivity": 1},
      {"name": "checker", "color": "#e6e6e6", "unlit": true, "checker": {"color": "#191919", "cells_per_unit": 1}},
      {"name": "red", "color": "#d02020"}],
    "objects": [{"name": "mirror-sphere", "mesh": "mirror-sphere", "material": "mirror", "reflected": false,
                 "mirror": )" +
         mirror + R"(},
      {"name": "floor", "mesh": "floor", "material": "checker", "translation": [0, -1, 0]},
      {"name": "hidden-ball", "mesh": "ball", "material": "red", "translation": [-0.255, -0.766, -0.894]},
      {"name": "visible-ball", "mesh": "ball", "material": "red", "translation": [1.3, -0.6, 0.8]}],
    "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})";
}

void expectTheHiddenBallLeftOutAndTheSamePicture(const std::shared_ptr<const scene::Scene>& scene) {
  ASSERT_TRUE(scene);
  const PlannedAndEverything frames = renderBoth(scene);
  ASSERT_EQ(frames.needed.plan.size(), 1u);
  const render::MirrorPlanSummary& planned = frames.needed.plan[0];
  EXPECT_EQ(planned.culledObjects, 1u) << "the ball behind the mirror";
  EXPECT_EQ(planned.culledVertices, 65u * 33u);
  EXPECT_EQ(planned.searchedObjects, 2u) << "the floor and the visible ball";
  EXPECT_EQ(culledVertices(frames.everything), 0u);
  EXPECT_EQ(frames.needed.search.searched + planned.culledVertices, frames.everything.search.searched);
  // Without the planner every one of the ball's vertices is searched and found hidden: it never
  // showed, so leaving it out changes nothing.
  EXPECT_GE(frames.everything.search.hidden, frames.needed.search.hidden + planned.culledVertices);
  EXPECT_LE(frames.differingPixels, 2u);
}

}  // namespace

TEST(Planner, AnObjectInAnAnalyticSpheresShadowIsLeftOutAndThePictureStays) {
  expectTheHiddenBallLeftOutAndTheSamePicture(parse(
      sphereWithAHiddenBall(R"({"curvature": "convex", "analytic": {"sphere": {"center": [0, 0, 0], "radius": 1}}})")));
}

TEST(Planner, AnObjectInAMeshSpheresShadowIsLeftOutAndThePictureStays) {
  expectTheHiddenBallLeftOutAndTheSamePicture(parse(sphereWithAHiddenBall(R"({"curvature": "convex"})")));
}

// Sixteen 12 mm beacons 30-50 m around a mirror sphere: each image in the convex mirror is under
// half a pixel, so the default error budget leaves them out; at most one pixel each may change.
TEST(Planner, ObjectsWhoseImageIsUnderTheErrorBudgetAreLeftOutAndMoveAtMostAPixelEach) {
  std::string beacons;
  constexpr int kBeacons = 16;
  for (int i = 0; i < kBeacons; ++i) {
    const float angle = 0.4f * static_cast<float>(i), distance = 30.0f + 20.0f * static_cast<float>(i % 5) / 4.0f;
    beacons += R"(, {"name": "beacon-)" + std::to_string(i) +
               R"(", "mesh": "beacon", "material": "red", "translation": [)" +
               std::to_string(distance * std::sin(angle)) + ", " + std::to_string(0.5f * static_cast<float>(i % 4)) +
               ", " + std::to_string(distance * std::cos(angle)) + "]}";
  }
  // The declared sphere, and the same mesh without it: the rule reads bounds only.
  for (const std::string mirror :
       {R"({"curvature": "convex", "analytic": {"sphere": {"center": [0, 0, 0], "radius": 1}}})",
        R"({"curvature": "convex"})"}) {
    const auto scene = parse(R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#000000",
      "camera": {"eye": [1, 3, 3.5], "target": [0, -0.3, 0], "fov": 40},
      "meshes": [{"name": "mirror-sphere", "primitive": {"type": "sphere", "radius": 1, "slices": 64, "stacks": 32}},
        {"name": "floor", "primitive": {"type": "grid", "size": [16, 16], "cells": [16, 16]}},
        {"name": "beacon", "primitive": {"type": "sphere", "radius": 0.006, "slices": 8, "stacks": 4}}],
      "materials": [{"name": "mirror", "color": "#000000", "reflectivity": 1},
        {"name": "checker", "color": "#e6e6e6", "unlit": true, "checker": {"color": "#191919", "cells_per_unit": 1}},
        {"name": "red", "color": "#ff2020", "unlit": true}],
      "objects": [{"name": "mirror-sphere", "mesh": "mirror-sphere", "material": "mirror", "reflected": false,
                   "mirror": )" +
                             mirror + R"(},
        {"name": "floor", "mesh": "floor", "material": "checker", "translation": [0, -1, 0]})" +
                             beacons + R"(],
      "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})");
    ASSERT_TRUE(scene);
    const PlannedAndEverything frames = renderBoth(scene);
    ASSERT_EQ(frames.needed.plan.size(), 1u);
    const render::MirrorPlanSummary& planned = frames.needed.plan[0];
    const std::size_t beaconVertices = scene->meshes[scene->objects[2].mesh].vertices.size();
    EXPECT_EQ(planned.belowBudgetObjects, static_cast<std::size_t>(kBeacons));
    EXPECT_EQ(planned.belowBudgetVertices, kBeacons * beaconVertices);
    EXPECT_EQ(planned.searchedObjects, 1u) << "the floor";
    EXPECT_EQ(frames.needed.search.searched + planned.belowBudgetVertices, frames.everything.search.searched);
    EXPECT_LE(frames.differingPixels, static_cast<std::size_t>(kBeacons));
    std::printf("%d beacons under the budget: %zu of %u searches left out, %zu pixels differ\n", kBeacons,
                planned.belowBudgetVertices, frames.everything.search.searched, frames.differingPixels);
  }
}

// A mirror ball reflecting only mountains a kilometre away: within a 1 px budget a 1024-texel cube
// map serves it, except towards its silhouette, where the lookup's error grows past the budget and
// the pixels are ray-cast; the picture stays as close to the ray tracer as the searched one.
TEST(Planner, AMirrorReflectingOnlyFarMountainsUsesTheEnvironmentMapAndRayCastsItsRim) {
  // The declared sphere, and the same mesh without it (curvature from its edges, not the quadric).
  for (const std::string mirror :
       {R"({"curvature": "convex", "analytic": {"sphere": {"center": [0, 0, 0], "radius": 1}}})",
        R"({"curvature": "convex"})"}) {
    const auto scene = parse(R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#203040",
      "camera": {"eye": [1.0, 1.5, 5.7], "target": [0, 0, 0], "fov": 40},
      "meshes": [{"name": "ball", "primitive": {"type": "sphere", "radius": 1, "slices": 128, "stacks": 64}},
        {"name": "mountain", "primitive": {"type": "box", "size": [200, 120, 200]}}],
      "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9}, {"name": "red", "color": "#d02020"},
        {"name": "green", "color": "#20b040"}, {"name": "blue", "color": "#3050e0"}, {"name": "ground", "color": "#806040"}],
      "objects": [{"name": "ball", "mesh": "ball", "material": "chrome",
                   "mirror": )" +
                             mirror + R"(},
        {"name": "north", "mesh": "mountain", "material": "red", "translation": [0, 0, -1000]},
        {"name": "east", "mesh": "mountain", "material": "green", "translation": [1000, 30, 0]},
        {"name": "south", "mesh": "mountain", "material": "blue", "translation": [150, -90, 1000]},
        {"name": "west", "mesh": "mountain", "material": "ground", "translation": [-1000, -60, 150]}],
      "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})");
    ASSERT_TRUE(scene);
    specula::testing::Rig rig = specula::testing::makeRig(scene);
    ASSERT_TRUE(rig.renderer);
    const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
    passes::ReflectionSettings settings;
    settings.errorBudgetPixels = 1.0f;
    settings.environmentMapSize = 1024;
    auto planned = rig.renderer->render(pose, 640, 480, settings);
    ASSERT_TRUE(planned) << planned.error();
    ASSERT_EQ(planned->plan.size(), 1u);
    EXPECT_EQ(planned->plan[0].method, passes::PartMethod::EnvironmentMap);
    EXPECT_EQ(planned->search.searched, 0u);
    EXPECT_GT(planned->plan[0].uncoveredRayCast, 0u)
        << "the rim, where the lookup would be off by more than the budget";
    settings.plan = passes::PlanScope::Everything;
    auto searched = rig.renderer->render(pose, 640, 480, settings);
    ASSERT_TRUE(searched) << searched.error();
    const auto cube = specula::testing::mismatchAgainstRayTracer(scene, pose, *planned);
    const auto search = specula::testing::mismatchAgainstRayTracer(scene, pose, *searched);
    std::printf(
        "far mountains, mirror %s: environment map %.3f %%, %zu rim pixels ray-cast; searched %.3f %% of %zu mirror "
        "pixels\n",
        mirror.c_str(), 100.0 * cube.share, planned->plan[0].uncoveredRayCast, 100.0 * search.share,
        search.mirrorPixels);
    EXPECT_GT(cube.mirrorPixels, 10000u);
    EXPECT_LE(cube.share, search.share + 0.002);
  }
}

// A mirror cube split into its six flat faces: the three the camera cannot see search nothing, the
// others leave out the ball behind their plane, and the picture matches the ray tracer's.
TEST(Planner, FlatPartsLeaveOutWhatIsBehindThemAndPartsFacingAwaySearchNothing) {
  const auto scene = parse(R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#203040",
    "camera": {"eye": [2.5, 2.0, 3.0], "target": [0, 0, 0], "fov": 45},
    "meshes": [{"name": "cube", "primitive": {"type": "box", "size": [1.6, 1.6, 1.6]}},
      {"name": "floor", "primitive": {"type": "grid", "size": [16, 16], "cells": [16, 16]}},
      {"name": "ball", "primitive": {"type": "sphere", "radius": 0.3, "slices": 48, "stacks": 24}}],
    "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9},
      {"name": "checker", "color": "#e6e6e6", "unlit": true, "checker": {"color": "#191919", "cells_per_unit": 1}},
      {"name": "red", "color": "#d02020"}, {"name": "green", "color": "#20b040"}],
    "objects": [{"name": "cube", "mesh": "cube", "material": "chrome", "reflected": false, "mirror": {"curvature": "mixed"}},
      {"name": "floor", "mesh": "floor", "material": "checker", "translation": [0, -0.801, 0]},
      {"name": "front-ball", "mesh": "ball", "material": "red", "translation": [2.0, 0.2, 0.3]},
      {"name": "back-ball", "mesh": "ball", "material": "green", "translation": [-1.6, 0.3, -1.4]}],
    "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})");
  ASSERT_TRUE(scene);
  const PlannedAndEverything frames = renderBoth(scene);
  ASSERT_EQ(frames.needed.plan.size(), 6u) << "one part per face";
  int facingAway = 0, leavingOutTheBackBall = 0;
  for (const render::MirrorPlanSummary& part : frames.needed.plan) {
    if (part.facesAway) {
      ++facingAway;
      EXPECT_EQ(part.searchedObjects, 0u);
      EXPECT_EQ(part.culledObjects, 3u);
    } else if (part.culledObjects == 1) {
      ++leavingOutTheBackBall;
    }
  }
  EXPECT_EQ(facingAway, 3) << "the bottom and the two faces turned from the camera";
  EXPECT_GE(leavingOutTheBackBall, 2);
  EXPECT_LT(2 * frames.needed.search.searched, frames.everything.search.searched);
  EXPECT_LE(frames.differingPixels, 2u);

  const specula::testing::MirrorMismatch mismatch =
      specula::testing::mismatchAgainstRayTracer(scene, scene::ScenePose::at(*scene, 0.0), frames.needed);
  EXPECT_GT(mismatch.mirrorPixels, 10000u);
  std::printf("mirror cube, planned: %.2f %% of %zu mirror pixels differ from the ray tracer; %u searches against %u\n",
              100.0 * mismatch.share, mismatch.mirrorPixels, frames.needed.search.searched,
              frames.everything.search.searched);
  EXPECT_LE(mismatch.share, 0.01) << "the planned frame against the ray tracer";
}

// The ants' eyes and the kitchen bowl cover a few hundred to a few thousand pixels while reflecting
// tens of thousands of vertices, the checker sphere a third of the frame reflecting one floor: on
// llvmpipe the cost model predicts casting their pixels' rays cheaper, and it is exact.
TEST(Planner, MirrorsWhereCastingIsPredictedCheaperAreRayCastAndMatchTheRayTracer) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  ASSERT_TRUE(context) << context.error();
  for (const char* name : {"ants", "kitchen", "checker-sphere"}) {
    const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(name));
    auto renderer = render::Renderer::create(**context, scene);
    ASSERT_TRUE(renderer) << renderer.error();
    const scene::ScenePose pose = scene::ScenePose::at(*scene, 1.0);
    auto frame = (*renderer)->render(pose, 640, 480);
    ASSERT_TRUE(frame) << frame.error();
    ASSERT_FALSE(frame->plan.empty()) << name;
    for (const render::MirrorPlanSummary& part : frame->plan) {
      EXPECT_EQ(part.method, passes::PartMethod::RayCast) << name << ": ~" << part.projectedPixels << " px";
      EXPECT_LT(part.predictedCost.rayCast, part.predictedCost.search) << name;
    }
    EXPECT_EQ(frame->search.searched, 0u) << name << ": nothing searched";
    const double mismatch = specula::testing::mismatchAgainstRayTracer(scene, pose, *frame).share;
    std::printf("%s ray-cast: %.2f %% of its mirror pixels differ from the ray tracer\n", name, 100.0 * mismatch);
    EXPECT_LE(mismatch, 0.005) << name;

    passes::ReflectionSettings everything;
    everything.plan = passes::PlanScope::Everything;
    auto searched = (*renderer)->render(pose, 640, 480, everything);
    ASSERT_TRUE(searched) << searched.error();
    for (const render::MirrorPlanSummary& part : searched->plan)
      EXPECT_EQ(part.method, passes::PartMethod::VirtualObjects) << name;
    EXPECT_GT(searched->search.searched, 0u) << name << ": --plan everything searches";
  }
}

// Objects whose every triangle's image is smaller than the threshold skip the tessellation rounds:
// the ufo's far, finely meshed objects at a coarse 8 px threshold, and small kitchen objects in the
// bowl's outside at 4 px. The rounds may split some of them where a corner's search stopped at the
// part's edge (not a true image), which changes no pixel; the picture stays as the rounds draw it.
TEST(Planner, ObjectsPlannedUnsplitSkipTheRoundsAndThePictureStays) {
  for (const auto& [name, threshold] : {std::pair{"ufo", 8.0f}, std::pair{"kitchen", 4.0f}}) {
    const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(name));
    passes::ReflectionSettings settings;
    settings.tessellation.threshold = threshold;
    const PlannedAndEverything frames = renderBoth(scene, settings, {320, 240});
    const passes::TessellationStatistics& planned = frames.needed.tessellation;
    const passes::TessellationStatistics& rounds = frames.everything.tessellation;
    std::printf(
        "%s at %g px: %u objects planned unsplit; triangles into round 0 %u against %u, midpoint searches %u against "
        "%u, "
        "%zu pixels differ\n",
        name, static_cast<double>(threshold), planned.predictedUnsplitObjects, planned.trianglesPerRound.at(0),
        rounds.trianglesPerRound.at(0), planned.midpointSearches.searched, rounds.midpointSearches.searched,
        frames.differingPixels);
    EXPECT_GT(planned.predictedUnsplitObjects, 0u) << name;
    EXPECT_EQ(rounds.predictedUnsplitObjects, 0u) << name;
    EXPECT_EQ(planned.inputTriangles, rounds.inputTriangles) << name;
    EXPECT_LT(planned.trianglesPerRound.at(0), rounds.trianglesPerRound.at(0))
        << name << ": fewer triangles enter round 0";
    EXPECT_LE(frames.differingPixels, 2u) << name;
  }
}

// A flat mirror panel (a one-cell grid) with balls above and below it, seen exactly edge-on, from
// just above (grazing) and from above: the planner's rules leave the picture as --plan everything
// draws it, and what it casts by default matches the ray tracer.
TEST(Planner, AFlatMirrorSeenEdgeOnOrGrazingKeepsThePicture) {
  for (const float eyeHeight : {0.5f, 0.52f, 2.0f}) {
    const std::string json = R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#203040",
      "camera": {"eye": [0, )" +
                             std::to_string(eyeHeight) + R"(, 4], "target": [0, 0.5, 0], "fov": 45},
      "meshes": [{"name": "panel", "primitive": {"type": "grid", "size": [3, 3], "cells": [1, 1]}},
        {"name": "ball", "primitive": {"type": "sphere", "radius": 0.3, "slices": 32, "stacks": 16}}],
      "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9}, {"name": "red", "color": "#d02020"},
        {"name": "green", "color": "#20b040"}],
      "objects": [{"name": "panel", "mesh": "panel", "material": "chrome", "translation": [0, 0.5, 0], "mirror": {}},
        {"name": "above", "mesh": "ball", "material": "red", "translation": [0.3, 1.2, -0.4]},
        {"name": "below", "mesh": "ball", "material": "green", "translation": [-0.4, -0.3, 0.2]}],
      "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})";
    const auto scene = parse(json);
    ASSERT_TRUE(scene);
    SCOPED_TRACE("eye at height " + std::to_string(eyeHeight));
    const PlannedAndEverything frames = renderBoth(scene);
    EXPECT_LE(frames.differingPixels, 2u);
    for (const render::MirrorPlanSummary& part : frames.needed.plan) {
      EXPECT_TRUE(std::isfinite(part.projectedPixels));
      EXPECT_GE(part.culledObjects, 1u) << "the ball below the panel is behind it";
    }
    const specula::testing::MirrorMismatch mismatch = defaultFrameAgainstRayTracer(scene).mismatch;
    std::printf(
        "flat panel, eye at height %.2f: %zu pixels differ from --plan everything; %.2f %% of %zu mirror pixels from "
        "the "
        "ray tracer\n",
        static_cast<double>(eyeHeight), frames.differingPixels, 100.0 * mismatch.share, mismatch.mirrorPixels);
    if (mismatch.mirrorPixels > 100) {
      EXPECT_LE(mismatch.share, 0.01);
    }
  }
}

// A mirror sphere 80 m across seen from just outside it, the eye inside its bounding box: it may fill
// the frame, no image bound holds, and the planner must neither leave out nor shrink anything.
TEST(Planner, AHugeMirrorAroundTheEyesBoundsKeepsThePicture) {
  const auto scene = parse(R"({"specula_scene": 1, "ambient": [0.2, 0.2, 0.2], "background": "#203040",
    "camera": {"eye": [30, -5, 30], "target": [22, -14, 22], "fov": 50},
    "meshes": [{"name": "globe", "primitive": {"type": "sphere", "radius": 40, "slices": 256, "stacks": 128}},
      {"name": "ball", "primitive": {"type": "sphere", "radius": 0.8, "slices": 32, "stacks": 16}}],
    "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9}, {"name": "red", "color": "#d02020"},
      {"name": "green", "color": "#20b040"}, {"name": "blue", "color": "#3050e0"}],
    "objects": [{"name": "globe", "mesh": "globe", "material": "chrome", "translation": [0, -40.5, 0],
                 "mirror": {"curvature": "convex", "analytic": {"sphere": {"center": [0, -40.5, 0], "radius": 40}}}},
      {"name": "red", "mesh": "ball", "material": "red", "translation": [24, -11.5, 21]},
      {"name": "green", "mesh": "ball", "material": "green", "translation": [20, -12, 25]},
      {"name": "blue", "mesh": "ball", "material": "blue", "translation": [27, -7, 26]}],
    "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})");
  ASSERT_TRUE(scene);
  const PlannedAndEverything frames = renderBoth(scene);
  ASSERT_EQ(frames.needed.plan.size(), 1u);
  const render::MirrorPlanSummary& part = frames.needed.plan[0];
  EXPECT_EQ(part.projectedPixels, static_cast<double>(kWidth) * kHeight)
      << "the eye inside its bounds: it may fill the frame";
  EXPECT_EQ(part.belowBudgetObjects, 0u);
  EXPECT_EQ(part.searchedObjects, 3u);
  EXPECT_EQ(frames.needed.tessellation.predictedUnsplitObjects, 0u);
  EXPECT_LE(frames.differingPixels, 2u);

  const DefaultFrame planned = defaultFrameAgainstRayTracer(scene);
  ASSERT_EQ(planned.frame.plan.size(), 1u);
  const specula::testing::MirrorMismatch& mismatch = planned.mismatch;
  std::printf(
      "huge mirror: %zu pixels differ from --plan everything; planned (%s) %.2f %% of %zu mirror pixels from the ray "
      "tracer\n",
      frames.differingPixels, passes::partMethodName(planned.frame.plan[0].method), 100.0 * mismatch.share,
      mismatch.mirrorPixels);
  EXPECT_GT(mismatch.mirrorPixels, 50000u);
  EXPECT_LE(mismatch.share, 0.01);
}

// An object that was in the mirror's shadow, and so left out, moves into view: the very frame it can
// appear it is searched again (from its stale seeds) and drawn as without the planner.
TEST(Planner, AnObjectLeavingTheShadowReappearsTheFrameItCanBeSeen) {
  const auto scene = parse(sphereWithAHiddenBall(R"({"curvature": "convex"})"));
  ASSERT_TRUE(scene);
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  ASSERT_TRUE(context) << context.error();
  auto planned = render::Renderer::create(**context, scene);
  auto everything = render::Renderer::create(**context, scene);
  ASSERT_TRUE(planned && everything);
  std::size_t hiddenBall = 0;
  while (scene->objects[hiddenBall].name != "hidden-ball") ++hiddenBall;
  passes::ReflectionSettings searched;  // the planner would ray-cast the sphere, cheaper on llvmpipe
  searched.rayCast = passes::RayCastRule::Never;
  passes::ReflectionSettings all = searched;
  all.plan = passes::PlanScope::Everything;
  scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  for (int frame = 0; frame < 3; ++frame) {
    if (frame == 2) pose.objectToWorld[hiddenBall][3] = glm::vec4(-1.2f, -0.7f, 0.3f, 1.0f);  // beside the sphere
    auto withPlan = (*planned)->render(pose, kWidth, kHeight, searched);
    auto withoutPlan = (*everything)->render(pose, kWidth, kHeight, all);
    ASSERT_TRUE(withPlan && withoutPlan);
    EXPECT_EQ(withPlan->plan[0].culledObjects, frame < 2 ? 1u : 0u) << "frame " << frame;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < withPlan->rgba.size(); i += 4)
      for (std::size_t c = 0; c < 3; ++c)
        if (std::abs(withPlan->rgba[i + c] - withoutPlan->rgba[i + c]) > 2) {
          ++differing;
          break;
        }
    EXPECT_LE(differing, 2u) << "frame " << frame;
  }
}
