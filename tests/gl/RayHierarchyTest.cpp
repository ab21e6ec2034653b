// Szabo's ray hierarchy (--search hierarchy), read back and checked on the CPU: every node must bound
// what its children bound, and every visible vertex must lie in the cones, so the traversal needs no
// enlargement (Szabo's leaves are points, whose gaps his enlargement papers over; ours cover cells).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "SceneRig.h"
#include "passes/ReflectedVertex.h"
#include "scene/ScenePose.h"

namespace specula::testing {
namespace {

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

struct HierarchyCase {
  const char* scene;
  double time;
};

class RayHierarchy : public ::testing::TestWithParam<HierarchyCase> {};

// Level by level: each child's sphere inside its parent's, each child's cone inside its parent's
// (a parent's cone of half-angle π holds every direction), and no child under a parent marked empty.
TEST_P(RayHierarchy, EveryNodeBoundsItsChildren) {
  Rig rig = makeRig(GetParam().scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), GetParam().time);
  ASSERT_TRUE(rig.renderer->render(pose, 320, 240, withSearch(passes::SearchStrategy::Hierarchy)));
  const int top = rig.renderer->rayHierarchyTopLevel();
  ASSERT_GT(top, 4);
  auto finer = rig.renderer->readRayHierarchyLevel(0);
  std::size_t mirrorLeaves = 0;
  for (const glm::vec4& sphere : finer.spheres) mirrorLeaves += sphere.w >= 0.0f;
  EXPECT_GT(mirrorLeaves, 50u) << "the mirror is in view";
  for (int level = 1; level <= top; ++level) {
    const auto coarser = rig.renderer->readRayHierarchyLevel(level);
    ASSERT_EQ(coarser.size, glm::max(finer.size / 2, glm::ivec2(1))) << "GL mip sizes";
    const std::size_t layerTexels = static_cast<std::size_t>(finer.size.x) * static_cast<std::size_t>(finer.size.y);
    const std::size_t coarserLayerTexels =
        static_cast<std::size_t>(coarser.size.x) * static_cast<std::size_t>(coarser.size.y);
    int children = 0, outsideSphere = 0, outsideCone = 0, orphans = 0;
    for (std::size_t i = 0; i < finer.spheres.size(); ++i) {
      const glm::dvec4 sphere(finer.spheres[i]), cone(finer.cones[i]);
      if (sphere.w < 0.0) continue;
      const std::size_t layer = i / layerTexels, texel = i % layerTexels;
      const int x = static_cast<int>(texel % static_cast<std::size_t>(finer.size.x)),
                y = static_cast<int>(texel / static_cast<std::size_t>(finer.size.x));
      // The last texel of an odd row or column has three children.
      const glm::ivec2 parent = glm::min(glm::ivec2(x, y) / 2, coarser.size - 1);
      const std::size_t p = layer * coarserLayerTexels +
                            static_cast<std::size_t>(parent.y) * static_cast<std::size_t>(coarser.size.x) +
                            static_cast<std::size_t>(parent.x);
      const glm::dvec4 parentSphere(coarser.spheres[p]), parentCone(coarser.cones[p]);
      ++children;
      if (parentSphere.w < 0.0) {
        ++orphans;
        continue;
      }
      const double slack = 1e-5 * (1.0 + parentSphere.w);  // float rounding
      outsideSphere += glm::length(glm::dvec3(sphere) - glm::dvec3(parentSphere)) + sphere.w > parentSphere.w + slack;
      outsideCone += parentCone.w < 3.14159 &&
                     angleBetween(glm::dvec3(cone), glm::dvec3(parentCone)) + cone.w > parentCone.w + 1e-4;
    }
    EXPECT_GT(children, 0) << "level " << level;
    EXPECT_EQ(outsideSphere, 0) << "level " << level << ": spheres that do not bound their children";
    EXPECT_EQ(outsideCone, 0) << "level " << level << ": cones that do not bound their children";
    EXPECT_EQ(orphans, 0) << "level " << level << ": mirror texels under nodes marked empty";
    finer = coarser;
  }
}

// A vertex the traversal finds in no cone is searched again with enlarged cones, then down the
// nearest path. A visible vertex (one with a reflection point) must never need that; hidden ones
// (behind the silhouette) may.
TEST_P(RayHierarchy, EveryVisibleVertexLiesInACone) {
  Rig rig = makeRig(GetParam().scene);
  ASSERT_TRUE(rig.renderer);
  const scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), GetParam().time);
  auto frame = rig.renderer->render(pose, 640, 480, withSearch(passes::SearchStrategy::Hierarchy));
  ASSERT_TRUE(frame) << frame.error();
  std::size_t visible = 0, visibleEnlarged = 0, hiddenEnlarged = 0;
  for (const passes::ReflectedVertex& result : rig.renderer->readReflectedVertices()) {
    const int flags = result.state.w;
    if (flags & passes::ReflectedVertex::kUnsolved) continue;
    const bool enlarged = flags & (passes::ReflectedVertex::kEnlarged | passes::ReflectedVertex::kInNoCone);
    if (flags & passes::ReflectedVertex::kHidden) {
      hiddenEnlarged += enlarged;
      continue;
    }
    ++visible;
    visibleEnlarged += enlarged;
  }
  std::printf("%s t=%.0f: %zu visible vertices, %zu of them enlarged; %zu hidden enlarged; steps mean %.1f\n",
              GetParam().scene, GetParam().time, visible, visibleEnlarged, hiddenEnlarged,
              static_cast<double>(frame->search.totalSteps) /
                  static_cast<double>(std::max<std::size_t>(frame->search.searched, 1)));
  EXPECT_GT(visible, 100u);
  EXPECT_EQ(visibleEnlarged, 0u);
  EXPECT_GE(frame->search.enlarged + frame->search.inNoCone, visibleEnlarged + hiddenEnlarged)
      << "the statistics count them";
}

INSTANTIATE_TEST_SUITE_P(Mirrors, RayHierarchy,
                         ::testing::Values(HierarchyCase{"checker-sphere", 0.0}, HierarchyCase{"mesh-sphere", 0.0},
                                           HierarchyCase{"mesh-sphere", 11.0}, HierarchyCase{"kitchen", 0.0},
                                           HierarchyCase{"kitchen", 10.0}),
                         [](const auto& test) {
                           std::string name =
                               std::string(test.param.scene) + "_t" + std::to_string(static_cast<int>(test.param.time));
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace specula::testing
