// The node rig: keyframe channels sampled as the glTF spec defines them, composed down the tree,
// looping per clip, carrying objects and the camera into the scene's pose.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/NodeRig.h"
#include "scene/SceneChecks.h"
#include "scene/ScenePose.h"
#include "scene/Primitives.h"

namespace specula::scene {
namespace {

glm::dvec4 rotationY(double degrees) {
  const double half = glm::radians(degrees) / 2;
  return {0.0, std::sin(half), 0.0, std::cos(half)};
}

NodeChannel channel(NodeProperty property, KeyInterpolation interpolation, std::vector<double> times,
                    std::vector<glm::dvec4> values) {
  NodeChannel c;
  c.property = property;
  c.interpolation = interpolation;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

void expectNear(const glm::dvec4& actual, const glm::dvec4& expected, double tolerance = 1e-9) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

TEST(NodeRig, LinearKeysInterpolateAndHoldTheEndsOutsideTheKeys) {
  const NodeChannel c =
      channel(NodeProperty::Translation, KeyInterpolation::Linear, {1.0, 3.0}, {{0, 0, 0, 0}, {4, -2, 8, 0}});
  expectNear(c.at(0.0), {0, 0, 0, 0});
  expectNear(c.at(1.5), {1, -0.5, 2, 0});
  expectNear(c.at(2.0), {2, -1, 4, 0});
  expectNear(c.at(7.0), {4, -2, 8, 0});
}

TEST(NodeRig, StepKeysJumpAtEachKeyTime) {
  const NodeChannel c =
      channel(NodeProperty::Scale, KeyInterpolation::Step, {0.0, 1.0, 2.0}, {{1, 1, 1, 0}, {2, 2, 2, 0}, {3, 3, 3, 0}});
  expectNear(c.at(0.999), {1, 1, 1, 0});
  expectNear(c.at(1.0), {2, 2, 2, 0});
  expectNear(c.at(1.999), {2, 2, 2, 0});
  expectNear(c.at(2.5), {3, 3, 3, 0});
}

// Rotations turn at a constant rate between keys (slerp), and the short way round: keys of 0° and 350°
// about y pass through -5°, not 175°.
TEST(NodeRig, LinearRotationsSlerpTheShortWay) {
  const NodeChannel quarter =
      channel(NodeProperty::Rotation, KeyInterpolation::Linear, {0.0, 1.0}, {rotationY(0), rotationY(90)});
  expectNear(quarter.at(1.0 / 3.0), rotationY(30), 1e-12);
  const NodeChannel wrap =
      channel(NodeProperty::Rotation, KeyInterpolation::Linear, {0.0, 1.0}, {rotationY(0), rotationY(350)});
  const glm::dvec4 halfway = wrap.at(0.5);
  const glm::dvec4 expected = rotationY(-5);
  EXPECT_NEAR(std::abs(glm::dot(halfway, expected)), 1.0, 1e-12) << "the same rotation, whatever its sign";
}

// The spec's Hermite spline, worked by hand: from 0 to 1 over 2 s with both tangents 1/s (so Δ·m = 2),
// p(w) = (-2w³ + 3w²) + 2(w³ - 2w² + w) + 2(w³ - w²) = 2w³ - 3w² + 2w; at w = ¼ that is 0.34375.
TEST(NodeRig, CubicSplinesFollowTheHermiteCurveWithTangentsScaledByTheKeySpan) {
  const NodeChannel c = channel(NodeProperty::Translation, KeyInterpolation::CubicSpline, {1.0, 3.0},
                                {{9, 9, 9, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {9, 9, 9, 0}});
  expectNear(c.at(1.5), {0.34375, 0, 0, 0});
  expectNear(c.at(2.0), {0.5, 0, 0, 0});
  expectNear(c.at(1.0), {0, 0, 0, 0});  // the value, not the in-tangent
  expectNear(c.at(4.0), {1, 0, 0, 0});
}

TEST(NodeRig, CubicSplineRotationsAreNormalized) {
  const NodeChannel c = channel(NodeProperty::Rotation, KeyInterpolation::CubicSpline, {0.0, 1.0},
                                {{0, 0, 0, 0}, rotationY(0), {0, 1, 0, 0}, {0, 1, 0, 0}, rotationY(120), {0, 0, 0, 0}});
  EXPECT_NEAR(glm::length(c.at(0.3)), 1.0, 1e-12);
}

// A carousel: a parent turning about y carries a child placed 2 along x; each clip loops on its own length.
TEST(NodeRig, ClipsTurnParentsThatCarryTheirChildrenAndLoopOnTheirOwnDuration) {
  NodeRig rig;
  rig.nodes.resize(2);
  rig.nodes[1].parent = 0;
  rig.nodes[1].translation = {2, 0, 0};
  NodeClip turn{"turn",
                {channel(NodeProperty::Rotation, KeyInterpolation::Linear, {0.0, 1.0, 2.0},
                         {rotationY(0), rotationY(90), rotationY(180)})},
                2.0};
  NodeClip lift{
      "lift",
      {channel(NodeProperty::Translation, KeyInterpolation::Linear, {0.0, 3.0}, {{0, 0, 0, 0}, {0, 3, 0, 0}})},
      3.0};
  lift.channels[0].node = 1;
  lift.channels[0].values = {{2, 0, 0, 0}, {2, 3, 0, 0}};
  rig.clips = {turn, lift};
  ASSERT_EQ(rigProblem(rig, 0), std::nullopt);
  const auto childAt = [&](double t) { return glm::dvec3(rig.worldAt(t)[1] * glm::dvec4(0, 0, 0, 1)); };
  // At 1 s: turned 90° about y, so +x went to -z; lifted by 1.
  const glm::dvec3 one = childAt(1.0);
  EXPECT_NEAR(one.x, 0.0, 1e-9);
  EXPECT_NEAR(one.y, 1.0, 1e-9);
  EXPECT_NEAR(one.z, -2.0, 1e-9);
  // At 2.5 s the turn has looped to 0.5 s (45°) while the lift, 3 s long, is at 2.5.
  const glm::dvec3 later = childAt(2.5);
  EXPECT_NEAR(later.x, 2.0 * std::cos(glm::radians(45.0)), 1e-9);
  EXPECT_NEAR(later.y, 2.5, 1e-9);
  EXPECT_NEAR(later.z, -2.0 * std::sin(glm::radians(45.0)), 1e-9);
  // A clock running backwards wraps too: -0.5 s is 1.5 s into the turn and 2.5 s into the lift.
  const glm::dvec3 before = childAt(-0.5);
  EXPECT_NEAR(before.x, 2.0 * std::cos(glm::radians(135.0)), 1e-9);
  EXPECT_NEAR(before.y, 2.5, 1e-9);
}

TEST(NodeRig, AScaleAnimatedToZeroLeavesATinyButInvertibleTransform) {
  NodeRig rig;
  rig.nodes.resize(1);
  rig.clips = {{"vanish",
                {channel(NodeProperty::Scale, KeyInterpolation::Linear, {0.0, 1.0}, {{1, 1, 1, 0}, {0, -0, 0, 0}})},
                1.0}};
  const glm::dmat4 world = rig.worldAt(0.999999999)[0];
  EXPECT_NEAR(std::abs(glm::determinant(glm::dmat3(world))), std::pow(kMinNodeScale, 3), 1e-15);
  EXPECT_TRUE(std::isfinite(glm::determinant(glm::inverse(glm::dmat3(world)))));
}

// The pose puts a rigged object at its object transform (an include's placement) times its node's world.
TEST(NodeRig, ThePoseDrawsRiggedObjectsAtTheirNodeAndTheCameraAtItsNode) {
  Scene scene;
  scene.meshes.push_back(primitives::box("box", {1.0f, 1.0f, 1.0f}));
  scene.materials.emplace_back();
  scene.objects.resize(2);
  scene.objects[0].name = "rigged";
  scene.objects[0].transform.translation = {0, 0, 10};
  scene.objects[1].name = "still";
  scene.rig.nodes.resize(2);
  scene.rig.nodes[1].parent = 0;
  scene.rig.clips = {
      {"slide",
       {channel(NodeProperty::Translation, KeyInterpolation::Linear, {0.0, 1.0}, {{0, 0, 0, 0}, {4, 0, 0, 0}})},
       1.0}};
  scene.rig.objects = {{0, 1}};
  scene.rig.camera = RiggedCamera{1, 50.0f};
  ASSERT_EQ(sceneProblem(scene), std::nullopt);
  EXPECT_TRUE(scene.moves());
  const ScenePose pose = ScenePose::at(scene, 0.5);
  const glm::vec3 rigged(pose.objectToWorld[0] * glm::vec4(0, 0, 0, 1));
  EXPECT_NEAR(rigged.x, 2.0f, 1e-6f);
  EXPECT_NEAR(rigged.z, 10.0f, 1e-6f);
  EXPECT_EQ(pose.objectToWorld[1], glm::mat4(1.0f));
  EXPECT_NEAR(pose.camera.eye.x, 2.0f, 1e-6f);
  EXPECT_NEAR(pose.camera.fovYDegrees, 50.0f, 1e-6f);
  EXPECT_LT(pose.camera.target.z, pose.camera.eye.z) << "a glTF camera looks down its -z";
}

TEST(NodeRig, BrokenRigsAreNamed) {
  const auto problem = [](const std::function<void(NodeRig&)>& edit) {
    NodeRig rig;
    rig.nodes.resize(2);
    rig.clips = {
        {"c",
         {channel(NodeProperty::Translation, KeyInterpolation::Linear, {0.0, 1.0}, {{0, 0, 0, 0}, {1, 0, 0, 0}})},
         1.0}};
    edit(rig);
    return rigProblem(rig, 1).value_or("");
  };
  EXPECT_EQ(problem([](NodeRig&) {}), "");
  EXPECT_NE(problem([](NodeRig& r) { r.nodes[0].parent = 1; }).find("parent must come before"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.clips[0].channels[0].node = 2; }).find("out of range"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.nodes[0].matrix = glm::dmat4(1.0); }).find("matrix node"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) {
              r.clips[0].channels[0].times = {0.5, 0.5};
            }).find("increase strictly"),
            std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.clips[0].channels[0].values.pop_back(); }).find("miscount"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.clips[0].duration = 2.0; }).find("duration"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.objects = {{1, 0}}; }).find("rigged object"), std::string::npos);
  EXPECT_NE(problem([](NodeRig& r) { r.camera = RiggedCamera{0, 180.0f}; }).find("camera"), std::string::npos);
}

// What the renderer relies on of deforming objects, refused by name when broken.
TEST(NodeRig, BrokenDeformationsAreNamed) {
  const auto problem = [](const std::function<void(Scene&)>& edit) {
    Scene scene;
    scene.meshes.push_back(primitives::box("box", {1.0f, 1.0f, 1.0f}));
    scene.meshes[0].morphTargets.push_back({std::vector<glm::vec3>(scene.meshes[0].vertices.size()), {}});
    scene.materials.emplace_back();
    scene.objects.resize(1);
    scene.objects[0].name = "box";
    scene.rig.nodes.resize(1);
    scene.rig.clips = {
        {"c",
         {channel(NodeProperty::Weights, KeyInterpolation::Linear, {0.0, 1.0}, {{0, 0, 0, 0}, {1, 0, 0, 0}})},
         1.0}};
    scene.rig.objects = {{0, 0}};
    scene.rig.morphed = {{0, 0, {0.0f}}};
    edit(scene);
    return sceneProblem(scene).value_or("");
  };
  EXPECT_EQ(problem([](Scene&) {}), "");
  EXPECT_NE(problem([](Scene& s) {
              s.objects.push_back(s.objects[0]);
              s.objects.back().name = "twin";
            }).find("other objects use too"),
            std::string::npos);
  EXPECT_NE(problem([](Scene& s) { s.rig.morphed[0].restWeights.push_back(1.0f); }).find("one rest weight"),
            std::string::npos);
  EXPECT_NE(problem([](Scene& s) { s.meshes[0].morphTargets[0].positions.pop_back(); }).find("one position"),
            std::string::npos);
  EXPECT_NE(problem([](Scene& s) { s.meshes[0].morphTargets[0].positions[0].x = 1e10f; }).find("beyond"),
            std::string::npos);
  EXPECT_NE(problem([](Scene& s) {
              s.objects[0].mirror = MirrorInfo{};
              s.objects[0].mirror->analytic = AnalyticShape{};
            }).find("changes shape"),
            std::string::npos);
  // A skin: its joints in range, and every vertex's weights on joints it has, summing to 1.
  const auto skinned = [](Scene& s) {
    s.rig.skins = {{{0}, {glm::dmat4(1.0)}}};
    s.rig.skinned = {{0, 0, 0}};
    const std::size_t n = s.meshes[0].vertices.size();
    s.meshes[0].influences = {
        {std::vector<glm::uvec4>(n, glm::uvec4(0)), std::vector<glm::vec4>(n, glm::vec4(1, 0, 0, 0))}};
  };
  EXPECT_EQ(problem(skinned), "");
  EXPECT_NE(problem([&](Scene& s) {
              skinned(s);
              s.meshes[0].influences[0].joints[3].x = 2;
            }).find("follows joint 2, but its skin has 1"),
            std::string::npos);
  EXPECT_NE(problem([&](Scene& s) {
              skinned(s);
              s.meshes[0].influences[0].weights[3] = {0.5f, 0.0f, 0.0f, 0.0f};
            }).find("do not sum to 1"),
            std::string::npos);
  EXPECT_NE(problem([&](Scene& s) {
              skinned(s);
              s.rig.skins[0].joints = {4};
            }).find("joint is out of range"),
            std::string::npos);
}

}  // namespace
}  // namespace specula::scene
