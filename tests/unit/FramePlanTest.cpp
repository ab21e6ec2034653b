// The frame graph is plain data: which passes run for a view, decided without GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "passes/FramePlan.h"
#include "passes/MeasuredCosts.h"
#include "scene/Primitives.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "scene/builtin/SceneAssembly.h"

using namespace specula;

namespace {

std::vector<math::Bounds> worldBounds(const scene::Scene& scene, const scene::ScenePose& pose) {
  std::vector<math::Bounds> bounds;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    math::Bounds local;
    for (const scene::Vertex& v : scene.meshes[scene.objects[i].mesh].vertices) local.add(v.position);
    bounds.push_back(local.transformed(pose.objectToWorld[i]));
  }
  return bounds;
}

// `scene` with a box of side `size` added at `centre`, reflected in its mirrors.
scene::Scene withBox(scene::Scene scene, const glm::vec3& centre, float size) {
  const std::uint32_t mesh = scene::builtin::addMesh(scene, scene::primitives::box("probe-box", glm::vec3(size)));
  scene::builtin::addObject(scene, "probe", mesh, 0, scene::builtin::placed(centre));
  return scene;
}

// The plan's passes by name.
std::vector<std::string_view> names(const std::vector<passes::PassId>& passes) {
  std::vector<std::string_view> result;
  for (passes::PassId pass : passes) result.push_back(passes::passName(pass));
  return result;
}

// Default settings tessellate reflected geometry adaptively.
const std::vector<std::string_view> kReflectionPasses{"scene",  "mirror-gbuffer", "gbuffer-pyramid",
                                                      "search", "tessellation",   "virtual-objects"};

}  // namespace

TEST(FramePlan, VisibleMirrorRunsTheReflectionPassesForEveryOtherReflectedObject) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  ASSERT_EQ(slots.mirrors.size(), 1u);
  EXPECT_EQ(slots.mirrors[0].reflected.size(), 1u) << "the sphere reflects the floor, not itself";
  EXPECT_EQ(slots.slotCount, scene.meshes[scene.objects[slots.mirrors[0].reflected[0].object].mesh].vertices.size());
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  const passes::FramePlan plan =
      passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), searched);
  EXPECT_EQ(names(plan.passes), kReflectionPasses);
  EXPECT_TRUE(plan.tessellate);
  ASSERT_EQ(plan.mirrors.size(), 1u);
}

TEST(FramePlan, TessellationOffOrAtLevelZeroRunsNoTessellationPass) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  for (const auto& [mode, level] :
       {std::pair{passes::TessellationMode::None, 4}, std::pair{passes::TessellationMode::Paper, 0}}) {
    passes::ReflectionSettings settings;
    settings.rayCast = passes::RayCastRule::Never;
    settings.tessellation.mode = mode;
    settings.tessellation.maxLevel = level;
    const passes::FramePlan plan =
        passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), settings);
    EXPECT_FALSE(plan.tessellate);
    EXPECT_EQ(std::count(plan.passes.begin(), plan.passes.end(), passes::PassId::Tessellation), 0);
    EXPECT_EQ(plan.passes.back(), passes::PassId::VirtualObjects);
  }
}

TEST(FramePlan, MirrorOutOfViewRunsOnlyTheScenePass) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  pose.camera = {{0.0f, 2.0f, 5.0f}, {0.0f, 2.0f, 10.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};  // looking away
  const passes::FramePlan plan = passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), {});
  EXPECT_EQ(names(plan.passes), std::vector<std::string_view>{"scene"});
  EXPECT_TRUE(plan.mirrors.empty());
}

TEST(FramePlan, MethodNoneRunsOnlyTheScenePass) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::None;
  const passes::FramePlan plan = passes::planFrame(passes::ReflectionSlots::forScene(scene), pose,
                                                   worldBounds(scene, pose), glm::ivec2(640, 480), settings);
  EXPECT_EQ(names(plan.passes), std::vector<std::string_view>{"scene"});
}

TEST(FramePlan, OnlyVisibleMirrorsOfSeveralAreSearched) {
  const scene::Scene scene = *scene::makeBuiltinScene("ants");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  ASSERT_EQ(slots.mirrors.size(), 8u);
  scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  const auto bounds = worldBounds(scene, pose);
  // Aim a narrow camera at one eye: the other seven are outside the frustum.
  const glm::vec3 eye = bounds[slots.mirrors[0].mirrorObject].center();
  pose.camera = {eye + glm::vec3(0.0f, 0.05f, 0.3f), eye, {0.0f, 1.0f, 0.0f}, 2.0f};
  const passes::FramePlan plan = passes::planFrame(slots, pose, bounds, glm::ivec2(480, 480), {});
  ASSERT_FALSE(plan.mirrors.empty());
  EXPECT_LT(plan.mirrors.size(), 8u);
  EXPECT_EQ(plan.mirrors[0].slots->mirrorObject, slots.mirrors[0].mirrorObject);
}

TEST(FramePlan, ObjectsMarkedNotReflectedGetNoSlots) {
  scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  for (scene::SceneObject& object : scene.objects)
    if (!object.mirror) object.reflected = false;
  const auto slots = passes::ReflectionSlots::forScene(scene);
  ASSERT_EQ(slots.mirrors.size(), 1u);
  EXPECT_TRUE(slots.mirrors[0].reflected.empty());
  EXPECT_EQ(slots.slotCount, 0u);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  // Nothing to search: the mirror is planned for the environment it reflects alone.
  const passes::FramePlan plan = passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(480, 480), {});
  EXPECT_EQ(names(plan.passes), (std::vector<std::string_view>{"scene", "mirror-gbuffer", "virtual-objects"}));
  ASSERT_EQ(plan.mirrors.size(), 1u);
  EXPECT_EQ(plan.mirrors[0].method, passes::PartMethod::OwnColour);
}

TEST(FrustumTest, BoxJustOutsideTheWidenedSideIsCulledAndInsideIsKept) {
  const math::Camera camera{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}, 90.0f};
  auto box = [](glm::vec3 c) {
    math::Bounds b;
    b.add(c - glm::vec3(0.1f));
    b.add(c + glm::vec3(0.1f));
    return b;
  };
  EXPECT_TRUE(passes::boundsInFrustum(box({0.0f, 0.0f, -5.0f}), camera, 1.0f, 0.0f));
  EXPECT_FALSE(passes::boundsInFrustum(box({0.0f, 0.0f, 5.0f}), camera, 1.0f, 0.0f)) << "behind the eye";
  EXPECT_FALSE(passes::boundsInFrustum(box({6.0f, 0.0f, -5.0f}), camera, 1.0f, 0.0f)) << "beyond the 45° side";
  EXPECT_TRUE(passes::boundsInFrustum(box({5.0f, 0.0f, -5.0f}), camera, 1.0f, 0.0f)) << "straddles the side";
  EXPECT_FALSE(passes::boundsInFrustum(math::Bounds{}, camera, 1.0f, 0.0f)) << "empty";
}

TEST(FramePlan, TheEnvironmentMapBaselineRunsNoSearchPyramidOrTessellation) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::EnvironmentMap;
  const passes::FramePlan plan =
      passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), settings);
  EXPECT_EQ(names(plan.passes), (std::vector<std::string_view>{"scene", "mirror-gbuffer", "environment-map"}));
  EXPECT_FALSE(plan.tessellate);
  EXPECT_EQ(plan.mirrors.size(), 1u);
}

TEST(FramePlan, HalfFloatGBuffersAreKeptOnlyForMirrorsNearTheOrigin) {
  const auto sphere = [](const glm::vec3& centre, float radius) {
    math::Bounds bounds;
    bounds.add(centre - glm::vec3(radius));
    bounds.add(centre + glm::vec3(radius));
    return bounds;
  };
  EXPECT_TRUE(passes::halfFloatsResolve(sphere(glm::vec3(0.0f), 1.0f)));
  EXPECT_TRUE(passes::halfFloatsResolve(sphere({3.0f, 0.0f, 0.0f}, 1.0f)));
  EXPECT_FALSE(passes::halfFloatsResolve(sphere({1000.0f, 0.0f, 0.0f}, 1.0f)));
  EXPECT_TRUE(passes::halfFloatsResolve(sphere({1000.0f, 0.0f, 0.0f}, 200.0f)))
      << "what counts is the distance in radii";

  scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  passes::ReflectionSettings settings;
  settings.gbufferPrecision = passes::GBufferPrecision::Float16;
  EXPECT_EQ(passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), settings).gbufferPrecision,
            passes::GBufferPrecision::Float16);
  const glm::vec3 far(5000.0f, 0.0f, 0.0f);  // the whole scene and camera moved away from the origin
  for (glm::mat4& objectToWorld : pose.objectToWorld)
    objectToWorld = glm::translate(glm::mat4(1.0f), far) * objectToWorld;
  pose.camera.eye += far;
  pose.camera.target += far;
  EXPECT_EQ(passes::planFrame(slots, pose, worldBounds(scene, pose), glm::ivec2(640, 480), settings).gbufferPrecision,
            passes::GBufferPrecision::Float32);
}

TEST(FramePlan, APartIsRayCastWhereThatIsPredictedCheaperAndThenNeedsNoSearchPasses) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  const auto bounds = worldBounds(scene, pose);
  const double large = passes::projectedPixels(bounds[slots.mirrors[0].mirrorObject], pose.camera, {640, 480});
  const double small = passes::projectedPixels(bounds[slots.mirrors[0].mirrorObject], pose.camera, {64, 48});
  EXPECT_NEAR(small * 100.0, large, 1e-6 * large) << "pixels scale with the frame's area";

  // One light floor: a cast per pixel costs less than the search's share of the pyramid and rounds.
  const passes::FramePlan rayCast = passes::planFrame(slots, pose, bounds, {640, 480}, {});
  ASSERT_EQ(rayCast.mirrors.size(), 1u);
  EXPECT_EQ(rayCast.mirrors[0].method, passes::PartMethod::RayCast);
  EXPECT_LT(rayCast.mirrors[0].cost.rayCast, rayCast.mirrors[0].cost.search);
  EXPECT_EQ(names(rayCast.passes), (std::vector<std::string_view>{"scene", "mirror-gbuffer", "virtual-objects"}));
  EXPECT_FALSE(rayCast.tessellate);

  // Twelve more light objects around it at 1280x720: thirteen casts per pixel cost more than
  // searching their few hundred vertices.
  scene::Scene crowded = scene;
  for (int i = 0; i < 12; ++i) {
    const float angle = 0.5236f * static_cast<float>(i);
    crowded = withBox(crowded, {3.0f * std::cos(angle), 0.0f, 3.0f * std::sin(angle)}, 0.3f);
  }
  const auto crowdedSlots = passes::ReflectionSlots::forScene(crowded);
  const scene::ScenePose crowdedPose = scene::ScenePose::at(crowded, 0.0);
  const passes::FramePlan searched =
      passes::planFrame(crowdedSlots, crowdedPose, worldBounds(crowded, crowdedPose), {1280, 720}, {});
  ASSERT_EQ(searched.mirrors.size(), 1u);
  EXPECT_GE(searched.mirrors[0].reflected.size(), 10u);
  EXPECT_EQ(searched.mirrors[0].method, passes::PartMethod::VirtualObjects);
  EXPECT_GT(searched.mirrors[0].cost.rayCast, searched.mirrors[0].cost.search);
  EXPECT_TRUE(searched.tessellate);

  // The rules that override the cost model.
  passes::ReflectionSettings never, always, everything;
  never.rayCast = passes::RayCastRule::Never;
  always.rayCast = passes::RayCastRule::Always;
  everything.plan = passes::PlanScope::Everything;
  EXPECT_EQ(passes::planFrame(slots, pose, bounds, {64, 48}, never).mirrors[0].method,
            passes::PartMethod::VirtualObjects);
  EXPECT_EQ(passes::planFrame(crowdedSlots, crowdedPose, worldBounds(crowded, crowdedPose), {1280, 720}, always)
                .mirrors[0]
                .method,
            passes::PartMethod::RayCast);
  EXPECT_EQ(passes::planFrame(slots, pose, bounds, {64, 48}, everything).mirrors[0].method,
            passes::PartMethod::VirtualObjects);

  // The eye inside the mirror's bounds: it may fill the frame.
  math::Camera inside = pose.camera;
  inside.eye = bounds[slots.mirrors[0].mirrorObject].center();
  inside.target = inside.eye + glm::vec3(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(passes::projectedPixels(bounds[slots.mirrors[0].mirrorObject], inside, {64, 48}), 64.0 * 48.0);
}

// Casting grows with pixels times objects; searching with the objects' vertices and triangles.
TEST(FramePlan, ThePredictedCostsFollowPixelsObjectsAndGeometry) {
  passes::ReflectionSlotRange light{0, 0, 100, 150}, heavy{1, 100, 30000, 60000};
  const std::vector<const passes::ReflectionSlotRange*> one{&light}, two{&light, &light}, big{&heavy};
  const passes::PartCost base = passes::predictPartCost(10000.0, one);
  const double doubled = passes::predictPartCost(20000.0, two).rayCast;
  EXPECT_GT(doubled, 3.5 * base.rayCast) << "twice the pixels for twice the objects";
  EXPECT_LE(doubled, 4.0 * base.rayCast);
  EXPECT_GT(passes::predictPartCost(10000.0, big).search, 10.0 * base.search);
  EXPECT_DOUBLE_EQ(passes::predictPartCost(10000.0, big).rayCast, base.rayCast) << "a cast per pixel whatever the mesh";
  EXPECT_EQ(passes::predictPartCost(10000.0, {}).rayCast, 0.0);
}

TEST(FramePlan, TheSameViewGivesTheSamePlan) {
  const scene::Scene scene = *scene::makeBuiltinScene("ants");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 2.5);
  const auto bounds = worldBounds(scene, pose);
  const passes::FramePlan first = passes::planFrame(slots, pose, bounds, {640, 480}, {});
  const passes::FramePlan second = passes::planFrame(slots, pose, bounds, {640, 480}, {});
  EXPECT_EQ(first.passes, second.passes);
  ASSERT_EQ(first.mirrors.size(), second.mirrors.size());
  for (std::size_t i = 0; i < first.mirrors.size(); ++i) {
    EXPECT_EQ(first.mirrors[i].slots, second.mirrors[i].slots);
    EXPECT_EQ(first.mirrors[i].method, second.mirrors[i].method);
    EXPECT_EQ(first.mirrors[i].reflected, second.mirrors[i].reflected);
    EXPECT_EQ(first.mirrors[i].culledVertices, second.mirrors[i].culledVertices);
  }
}

TEST(FramePlan, AnErrorBudgetOutOfRangeIsRefusedByName) {
  passes::ReflectionSettings settings;
  for (float budget : {-0.1f, std::nanf(""), passes::kMaxErrorBudgetPixels + 0.5f}) {
    settings.errorBudgetPixels = budget;
    ASSERT_TRUE(passes::reflectionSettingsProblem(settings)) << budget;
    EXPECT_NE(passes::reflectionSettingsProblem(settings)->find("error-budget"), std::string::npos);
  }
  for (float budget : {0.0f, 0.5f, passes::kMaxErrorBudgetPixels}) {
    settings.errorBudgetPixels = budget;
    EXPECT_FALSE(passes::reflectionSettingsProblem(settings)) << budget;
  }
}

// The tessellation's GPU records hold a draw per round: a deeper level than the one limit is refused.
TEST(FramePlan, TheTessellationLevelIsBounded) {
  passes::ReflectionSettings settings;
  for (int level : {0, passes::kMaxTessellationLevel}) {
    settings.tessellation.maxLevel = level;
    EXPECT_FALSE(passes::reflectionSettingsProblem(settings)) << level;
  }
  for (int level : {-1, passes::kMaxTessellationLevel + 1}) {
    settings.tessellation.maxLevel = level;
    ASSERT_TRUE(passes::reflectionSettingsProblem(settings)) << level;
    EXPECT_NE(passes::reflectionSettingsProblem(settings)->find("level must lie in"), std::string::npos);
  }
}

// An image in a convex mirror is never larger than the object seen along the eye-mirror-object path,
// stretched as far off the view axis as the mirror reaches, nor than the mirror as drawn.
TEST(FramePlan, AConvexImageBoundFollowsThePathLength) {
  const math::Camera camera{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 45.0f};
  math::Bounds mirror;
  mirror.add(glm::vec3(-1.0f));
  mirror.add(glm::vec3(1.0f));
  const auto boxAt = [](const glm::vec3& centre, float half) {
    math::Bounds box;
    box.add(centre - glm::vec3(half));
    box.add(centre + glm::vec3(half));
    return box;
  };
  const double focal = 240.0 / std::tan(glm::radians(22.5));
  const math::Bounds far = boxAt({100.0f, 0.0f, 0.0f}, 0.01f);
  const double path = (5.0 - mirror.radius()) + (100.0 - mirror.radius() - far.radius());
  const double edge = std::asin(mirror.radius() / 5.0);  // the mirror's farthest point off the axis
  const double stretch = 1.0 / (std::cos(edge) * std::cos(edge));
  EXPECT_NEAR(passes::convexImageDiameterPixels(mirror, far, camera, {640, 480}),
              2.0 * focal * std::tan(std::asin(far.radius() / path)) * stretch, 1e-6);
  EXPECT_LT(passes::convexImageDiameterPixels(mirror, far, camera, {640, 480}), 0.5);
  EXPECT_GT(passes::convexImageDiameterPixels(mirror, boxAt({3.0f, 0.0f, 0.0f}, 0.5f), camera, {640, 480}), 10.0);
  const double mirrorDrawn = 2.0 * focal * std::tan(edge) * stretch;
  EXPECT_NEAR(passes::convexImageDiameterPixels(mirror, boxAt({1.5f, 0.0f, 0.0f}, 0.6f), camera, {640, 480}),
              mirrorDrawn, 1e-6)
      << "an object touching the mirror's bounds can fill it, and no more";
  // Off the view axis the same object may be drawn larger.
  math::Camera aside = camera;
  aside.target = {-2.0f, 0.0f, 0.0f};
  EXPECT_GT(passes::convexImageDiameterPixels(mirror, far, aside, {640, 480}),
            1.1 * passes::convexImageDiameterPixels(mirror, far, camera, {640, 480}));
  math::Camera inside = camera;
  inside.eye = {0.2f, 0.0f, 0.0f};
  EXPECT_TRUE(std::isinf(passes::convexImageDiameterPixels(mirror, far, inside, {640, 480})))
      << "the eye inside the mirror's bounds";
}

// Crack-free pixel tessellation searches only edges drawn at least the threshold long, and every
// edge long beside the mirror: an object whose every edge stays shorter is planned unsplit.
TEST(FramePlan, AnObjectNoEdgeOfWhichCanBeDrawnAsLongAsTheThresholdIsPlannedUnsplit) {
  const math::Camera camera{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 45.0f};
  math::Bounds mirror;
  mirror.add(glm::vec3(-1.0f));
  mirror.add(glm::vec3(1.0f));
  math::Bounds object;
  object.add(glm::vec3(19.0f, -1.0f, -1.0f));
  object.add(glm::vec3(21.0f, 1.0f, 1.0f));
  passes::TessellationSettings settings;
  settings.threshold = 4.0f;
  EXPECT_TRUE(passes::edgesStayUnsplit(mirror, object, 0.02, camera, {640, 480}, settings));
  EXPECT_FALSE(passes::edgesStayUnsplit(mirror, object, 0.5, camera, {640, 480}, settings))
      << "a longer edge may be drawn longer";
  settings.threshold = 0.1f;
  EXPECT_FALSE(passes::edgesStayUnsplit(mirror, object, 0.02, camera, {640, 480}, settings)) << "a finer threshold";
  settings.threshold = 4.0f;
  for (const auto mode : {passes::TessellationMode::Paper, passes::TessellationMode::None}) {
    passes::TessellationSettings other = settings;
    other.mode = mode;
    EXPECT_FALSE(passes::edgesStayUnsplit(mirror, object, 0.02, camera, {640, 480}, other))
        << "only crack-free decides by length";
  }
  passes::TessellationSettings angle = settings;
  angle.metric = passes::TessellationMetric::Angle;
  EXPECT_FALSE(passes::edgesStayUnsplit(mirror, object, 0.02, camera, {640, 480}, angle));
  // An edge longer than half its distance from the mirror splits whatever it shows.
  math::Bounds beside;
  beside.add(glm::vec3(1.5f, -0.1f, -0.1f));
  beside.add(glm::vec3(2.5f, 0.1f, 0.1f));
  settings.threshold = 1000.0f;
  EXPECT_TRUE(passes::edgesStayUnsplit(mirror, beside, 0.5, camera, {640, 480}, settings));
  EXPECT_FALSE(passes::edgesStayUnsplit(mirror, beside, 0.9, camera, {640, 480}, settings));
}

namespace {

// The planned part `part` of the scene's first mirror, for the scene's camera at t = 0.
passes::PlannedMirror plannedPart(const scene::Scene& scene, const passes::ReflectionSlots& slots, int part,
                                  const passes::ReflectionSettings& settings, glm::ivec2 frame = {640, 480}) {
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  const passes::FramePlan plan = passes::planFrame(slots, pose, worldBounds(scene, pose), frame, settings);
  for (const passes::PlannedMirror& planned : plan.mirrors)
    if (planned.slots->part == part) return planned;
  ADD_FAILURE() << "part " << part << " is not planned";
  return {};
}

bool reflects(const passes::PlannedMirror& planned, const std::string& name, const scene::Scene& scene) {
  return std::any_of(planned.reflected.begin(), planned.reflected.end(), [&](const passes::ReflectionSlotRange* range) {
    return scene.objects[range->object].name == name;
  });
}

}  // namespace

TEST(FramePlan, AnObjectWhoseImageIsUnderTheBudgetIsLeftOutOfConvexPartsOnly) {
  passes::ReflectionSettings searched;
  searched.rayCast = passes::RayCastRule::Never;
  passes::ReflectionSettings exact = searched;
  exact.errorBudgetPixels = 0.0f;
  passes::ReflectionSettings everything = searched;
  everything.plan = passes::PlanScope::Everything;

  // A 2 cm box 60 m beside the sphere: well under half a pixel in it.
  const scene::Scene far = withBox(*scene::makeBuiltinScene("checker-sphere"), {60.0f, 1.0f, 10.0f}, 0.02f);
  const auto slots = passes::ReflectionSlots::forScene(far);
  const passes::PlannedMirror budgeted = plannedPart(far, slots, 0, searched);
  EXPECT_FALSE(reflects(budgeted, "probe", far));
  EXPECT_EQ(budgeted.belowBudgetObjects, 1u);
  EXPECT_EQ(budgeted.belowBudgetVertices, 24u);
  EXPECT_TRUE(reflects(budgeted, "floor", far));
  EXPECT_TRUE(reflects(plannedPart(far, slots, 0, exact), "probe", far)) << "a zero budget keeps every object";
  EXPECT_TRUE(reflects(plannedPart(far, slots, 0, everything), "probe", far));

  // The same box next to the sphere is kept.
  const scene::Scene near = withBox(*scene::makeBuiltinScene("checker-sphere"), {2.0f, 1.0f, 1.0f}, 0.02f);
  EXPECT_TRUE(reflects(plannedPart(near, passes::ReflectionSlots::forScene(near), 0, searched), "probe", near));

  // A concave part can magnify any image: the kitchen bowl's inside keeps the far box, its outside does not.
  const scene::Scene kitchen = withBox(*scene::makeBuiltinScene("kitchen"), {60.0f, 1.0f, 10.0f}, 0.02f);
  const auto kitchenSlots = passes::ReflectionSlots::forScene(kitchen);
  const passes::PlannedMirror outside = plannedPart(kitchen, kitchenSlots, 0, searched);
  const passes::PlannedMirror inside = plannedPart(kitchen, kitchenSlots, 1, searched);
  ASSERT_EQ(outside.slots->kind, scene::SurfaceKind::Convex);
  ASSERT_EQ(inside.slots->kind, scene::SurfaceKind::Concave);
  EXPECT_FALSE(reflects(outside, "probe", kitchen));
  EXPECT_TRUE(reflects(inside, "probe", kitchen));
}

TEST(FramePlan, AMirrorNarrowerThanTheBudgetShowsItsOwnColour) {
  const scene::Scene scene = *scene::makeBuiltinScene("checker-sphere");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  const auto bounds = worldBounds(scene, pose);
  passes::ReflectionSettings wide;
  wide.errorBudgetPixels = passes::kMaxErrorBudgetPixels;
  // At 16x12 the sphere is about 13 px across: under a 16 px budget.
  const passes::FramePlan plan = passes::planFrame(slots, pose, bounds, {16, 12}, wide);
  ASSERT_EQ(plan.mirrors.size(), 1u);
  EXPECT_EQ(plan.mirrors[0].method, passes::PartMethod::OwnColour);
  EXPECT_TRUE(plan.mirrors[0].reflected.empty());
  EXPECT_EQ(plan.mirrors[0].belowBudgetObjects, 1u);
  EXPECT_FALSE(plan.search);
  EXPECT_EQ(names(plan.passes), (std::vector<std::string_view>{"scene", "mirror-gbuffer", "virtual-objects"}));
  EXPECT_STREQ(passes::partMethodName(plan.mirrors[0].method), "own-colour");
  EXPECT_EQ(passes::planFrame(slots, pose, bounds, {16, 12}, {}).mirrors[0].method, passes::PartMethod::RayCast)
      << "13 px is over the default half pixel";
}

// A direction error turns into a move of curvature radius / 2 per radian on the mirror.
TEST(FramePlan, TheEnvironmentMapReachFollowsParallaxTexelsAndCurvature) {
  const math::Camera camera{{0.0f, 0.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
  math::Bounds mirror;
  mirror.add(glm::vec3(-1.0f));
  mirror.add(glm::vec3(1.0f));
  const double focal = 240.0 / std::tan(glm::radians(20.0));
  const double capture = 2.0 * mirror.radius();
  EXPECT_NEAR(passes::environmentMapReach(mirror, 1.0, 800.0, camera, {640, 480}, 1024),
              focal * 0.5 * (capture / (800.0 - capture) + 2.0 / 1024.0), 1e-6);
  EXPECT_NEAR(passes::environmentMapReach(mirror, 2.0, 800.0, camera, {640, 480}, 1024),
              2.0 * passes::environmentMapReach(mirror, 1.0, 800.0, camera, {640, 480}, 1024), 1e-6);
  EXPECT_TRUE(std::isinf(
      passes::environmentMapReach(mirror, std::numeric_limits<double>::infinity(), 800.0, camera, {640, 480}, 1024)))
      << "a flat mirror shows parallax undiminished";
  EXPECT_TRUE(std::isinf(passes::environmentMapReach(mirror, 1.0, 2.0 * capture, camera, {640, 480}, 1024)))
      << "objects near the mirror";
}

TEST(FramePlan, AMirrorReflectingOnlyFarSurroundingsUsesTheEnvironmentMapWithinTheBudget) {
  // checker-sphere without its floor in the mirror, and four 200 m boxes a kilometre away.
  scene::Scene far = *scene::makeBuiltinScene("checker-sphere");
  for (scene::SceneObject& object : far.objects)
    if (!object.mirror) object.reflected = false;
  for (const glm::vec3 centre :
       {glm::vec3(0, 0, -1000), glm::vec3(1000, 30, 0), glm::vec3(150, -90, 1000), glm::vec3(-1000, -60, 150)})
    far = withBox(far, centre, 200.0f);
  passes::ReflectionSettings settings;
  settings.errorBudgetPixels = 2.0f;
  settings.environmentMapSize = 1024;
  const scene::ScenePose pose = scene::ScenePose::at(far, 0.0);
  const auto bounds = worldBounds(far, pose);
  const auto slots = passes::ReflectionSlots::forScene(far);
  const passes::FramePlan plan = passes::planFrame(slots, pose, bounds, {640, 480}, settings);
  ASSERT_EQ(plan.mirrors.size(), 1u);
  EXPECT_EQ(plan.mirrors[0].method, passes::PartMethod::EnvironmentMap);
  EXPECT_GT(plan.mirrors[0].environmentReach, 0.0f);
  EXPECT_EQ(plan.mirrors[0].reflected.size(), 4u) << "the cube captures what the mirror reflects";
  EXPECT_FALSE(plan.search);
  EXPECT_EQ(names(plan.passes),
            (std::vector<std::string_view>{"scene", "mirror-gbuffer", "virtual-objects", "environment-map"}));

  passes::ReflectionSettings exact = settings;
  exact.errorBudgetPixels = 0.0f;
  EXPECT_EQ(passes::planFrame(slots, pose, bounds, {640, 480}, exact).mirrors[0].method,
            passes::PartMethod::VirtualObjects);
  passes::ReflectionSettings coarse = settings;
  coarse.environmentMapSize = 64;  // a texel turns the reflection by more than the budget allows
  EXPECT_EQ(passes::planFrame(slots, pose, bounds, {640, 480}, coarse).mirrors[0].method,
            passes::PartMethod::VirtualObjects);

  // One box near the mirror brings the parallax back.
  const scene::Scene near = withBox(far, {3.0f, 0.0f, 0.0f}, 0.5f);
  const scene::ScenePose nearPose = scene::ScenePose::at(near, 0.0);
  EXPECT_EQ(passes::planFrame(passes::ReflectionSlots::forScene(near), nearPose, worldBounds(near, nearPose),
                              {640, 480}, settings)
                .mirrors[0]
                .method,
            passes::PartMethod::VirtualObjects);
}

// The planner measures the device: fed the times of a fake device on which searching is fifty times
// cheaper than the llvmpipe fit, it switches the kitchen's bowl to virtual objects within a few
// frames, predicts what it runs to within 25 %, and switches back when casting becomes the cheaper.
TEST(MeasuredCosts, ThePlanFollowsTheDeviceWithinAFewFramesAndBack) {
  const scene::Scene scene = *scene::makeBuiltinScene("kitchen");
  const auto slots = passes::ReflectionSlots::forScene(scene);
  const scene::ScenePose pose = scene::ScenePose::at(scene, 0.0);
  const auto bounds = worldBounds(scene, pose);
  const passes::ReflectionSettings planned;  // RayCastRule::WhenCheaper
  passes::MeasuredCosts costs;
  // The fake device: what each method takes, as a multiple of the fit.
  passes::CostRates device{0.02, 1.0};
  std::vector<passes::PartMethod> chosen;  // per frame the planner chose (exploration frames left out)
  double predicted = 0.0, took = 0.0;      // the last chosen frame's, summed over its parts
  const auto runFrames = [&](int frames) {
    for (int i = 0; i < frames; ++i) {
      const passes::MeasuredCosts::FrameRole role = costs.nextFrame();
      const passes::FramePlan plan =
          passes::planFrame(slots, pose, bounds, glm::ivec2(640, 480), planned, costs.rates(), role.explore);
      ASSERT_FALSE(plan.mirrors.empty());
      passes::PartCost fitted, measured;
      predicted = took = 0.0;
      for (const passes::PlannedMirror& mirror : plan.mirrors) {
        const bool searched = mirror.method == passes::PartMethod::VirtualObjects;
        ASSERT_TRUE(searched || mirror.method == passes::PartMethod::RayCast);
        (searched ? fitted.search : fitted.rayCast) += searched ? mirror.fittedCost.search : mirror.fittedCost.rayCast;
        (searched ? measured.search : measured.rayCast) +=
            searched ? mirror.fittedCost.search * device.search : mirror.fittedCost.rayCast * device.rayCast;
        predicted += searched ? mirror.cost.search : mirror.cost.rayCast;
      }
      took = measured.search + measured.rayCast;
      if (role.measure) costs.observe(fitted, measured);
      if (!role.explore) chosen.push_back(plan.mirrors[0].method);
      else EXPECT_EQ(plan.mirrors[0].method, *role.explore);
    }
  };
  // The fit alone ray-casts the bowl: the first frame says so.
  runFrames(1);
  ASSERT_EQ(chosen.front(), passes::PartMethod::RayCast);
  runFrames(9);
  EXPECT_EQ(chosen.back(), passes::PartMethod::VirtualObjects) << "after 10 frames, searching is known to be cheaper";
  EXPECT_NEAR(predicted, took, 0.25 * took) << "the prediction of what it runs";
  device = {10.0, 1.0};  // now searching is the dearer
  runFrames(40);
  EXPECT_EQ(chosen.back(), passes::PartMethod::RayCast) << "the measured search's cost turns the plan back";
  EXPECT_NEAR(predicted, took, 0.25 * took);
}

TEST(MeasuredCosts, AMeasurementMovesOnlyTheRatesOfTheMethodsThatRan) {
  passes::MeasuredCosts costs;
  costs.observe({10.0, 0.0}, {5.0, 0.0});
  EXPECT_EQ(costs.rates().search, 0.5) << "the first measurement replaces the fit";
  EXPECT_EQ(costs.rates().rayCast, 1.0);
  costs.observe({10.0, 0.0}, {15.0, 0.0});
  EXPECT_EQ(costs.rates().search, 0.5 + passes::MeasuredCosts::kLearningRate * (1.5 - 0.5))
      << "later ones move it part way";
  costs.observe({0.0, 4.0}, {0.0, 400000.0});  // an outlier moves a rate only so far
  EXPECT_GT(costs.rates().rayCast, 1.0);
  EXPECT_LE(costs.rates().rayCast, 1e3);
  const double before = costs.rates().search;
  costs.observe({10.0, 0.0}, {std::nan(""), 0.0});
  EXPECT_EQ(costs.rates().search, before) << "a time that is not a number teaches nothing";
}

TEST(MeasuredCosts, AnExplorationMeasuresTheMethodMeasuredLongestAgo) {
  passes::MeasuredCosts costs;
  EXPECT_FALSE(costs.nextFrame().measure) << "frame 0: shader compilation, not the device";
  ASSERT_TRUE(costs.nextFrame().measure);
  costs.observe({0.0, 4.0}, {0.0, 8.0});  // frame 1 ray-cast everything
  const passes::MeasuredCosts::FrameRole second = costs.nextFrame();
  ASSERT_TRUE(second.explore);
  EXPECT_EQ(*second.explore, passes::PartMethod::VirtualObjects);
  EXPECT_FALSE(second.measure) << "the other method's first frame compiles its shaders";
  const passes::MeasuredCosts::FrameRole third = costs.nextFrame();
  ASSERT_TRUE(third.explore);
  EXPECT_EQ(*third.explore, passes::PartMethod::VirtualObjects);
  EXPECT_TRUE(third.measure);
  costs.observe({6.0, 0.0}, {3.0, 0.0});
  int frame = 4;
  for (; frame < passes::MeasuredCosts::kExploreEvery; ++frame) {
    const passes::MeasuredCosts::FrameRole role = costs.nextFrame();
    EXPECT_FALSE(role.explore) << frame;
    EXPECT_EQ(role.measure, frame % passes::MeasuredCosts::kMeasureEvery == 0) << frame;
    if (role.measure) costs.observe({6.0, 0.0}, {3.0, 0.0});  // the plan searches now
  }
  const passes::MeasuredCosts::FrameRole explored = costs.nextFrame();
  ASSERT_TRUE(explored.explore);
  EXPECT_EQ(*explored.explore, passes::PartMethod::RayCast) << "casting was measured longest ago";
}
