// Screen-space tessellation of parametric meshes (issue #19, passes/PatchTessellation.h): the
// triangle count follows the projected size, triangles cover about the same pixel area from near
// and far, patches out of view cost nothing, and patches of different densities meet without cracks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "SceneRig.h"
#include "scene/ParametricMesh.h"
#include "scene/builtin/SceneAssembly.h"

using namespace specula;

namespace {

struct Tessellated {
  passes::PatchTessellationMeasure measure;
  render::RenderedFrame frame;
};

// One frame of `scene` from `camera` with the mirrors in their own colour, and its patch tessellation.
Tessellated tessellate(specula::testing::Rig& rig, const math::Camera& camera, int width = 640, int height = 480) {
  scene::ScenePose pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  pose.camera = camera;
  passes::ReflectionSettings settings;
  settings.method = passes::ReflectionMethod::None;
  auto frame = rig.renderer->render(pose, width, height, settings);
  EXPECT_TRUE(frame) << frame.error();
  if (!frame) return {};
  auto measure = rig.renderer->measurePatchTessellation(pose, *frame);
  EXPECT_TRUE(measure) << measure.error();
  if (!measure) return {};
  return {std::move(measure.value()), std::move(frame.value())};
}

double median(std::vector<float> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The camera `factor` times as far from its target along the same line of sight.
math::Camera movedAway(math::Camera camera, float factor) {
  camera.eye = camera.target + factor * (camera.eye - camera.target);
  return camera;
}

// A closed, convex rounded cube of six Bézier patches (one a face) whose neighbours share their
// boundary control points exactly, as every closed patch surface does.
std::vector<math::BezierPatch> roundedCube() {
  std::vector<math::BezierPatch> patches;
  const double steps[4] = {-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0};
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      math::BezierPatch patch;
      for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
          glm::dvec3 point;
          point[axis] = side;
          point[(axis + 1) % 3] = steps[column];
          point[(axis + 2) % 3] = steps[row];
          // Pulled towards the unit sphere: each point is a function of its position alone, so a
          // point two faces share comes out the same for both.
          patch.points[static_cast<std::size_t>(4 * row + column)] = point / std::sqrt(glm::length(point));
        }
      patches.push_back(patch);
    }
  return patches;
}

}  // namespace

TEST(PatchTessellation, TriangleCountFollowsProjectedSize) {
  const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("utah-teapot"));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  std::vector<Tessellated> views;
  for (const float factor : {1.0f, 2.0f, 4.0f}) views.push_back(tessellate(rig, movedAway(scene->camera, factor)));
  for (std::size_t i = 0; i < views.size(); ++i)
    std::printf("distance x%d: %zu triangles, median pixel area %.1f\n", 1 << i, views[i].measure.triangles,
                median(views[i].measure.pixelAreas));
  EXPECT_EQ(views[0].measure.patches, 32u);
  // Half the distance, twice the size on screen in each direction: about four times the triangles
  // while the patches are well above one segment a side.
  const double nearRatio =
      static_cast<double>(views[0].measure.triangles) / static_cast<double>(views[1].measure.triangles);
  EXPECT_GT(nearRatio, 2.5);
  EXPECT_LT(nearRatio, 5.0);
  EXPECT_GT(views[1].measure.triangles, views[2].measure.triangles);
  // What a triangle covers stays about the same, where the grid's would shrink fourfold.
  const double nearArea = median(views[0].measure.pixelAreas), farArea = median(views[1].measure.pixelAreas);
  EXPECT_GT(nearArea, 4.0);
  EXPECT_LT(nearArea, 40.0);
  EXPECT_LT(std::max(nearArea, farArea) / std::min(nearArea, farArea), 2.0);
}

TEST(PatchTessellation, PatchesOutOfViewAreDropped) {
  const auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("utah-teapot"));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  math::Camera away = scene->camera;
  away.target = away.eye + (away.eye - scene->camera.target);  // the teapot behind the eye
  const Tessellated behind = tessellate(rig, away);
  EXPECT_EQ(behind.measure.patches, 32u);
  EXPECT_EQ(behind.measure.triangles, 0u);
  const Tessellated whole = tessellate(rig, scene->camera);
  math::Camera aside = scene->camera;  // the teapot on the frame's left edge: its left half's patches go
  const glm::vec3 right = glm::normalize(glm::cross(aside.target - aside.eye, aside.up));
  aside.target += 4.5f * right;
  aside.eye += 4.5f * right;
  const Tessellated half = tessellate(rig, aside);
  EXPECT_GT(half.measure.triangles, 0u);
  EXPECT_LT(half.measure.triangles, whole.measure.triangles);
}

TEST(PatchTessellation, SeamsBetweenDifferentDensitiesAreClosed) {
  scene::Scene cube;
  cube.name = "rounded-cube";
  cube.background = {1.0f, 0.0f, 1.0f};
  cube.lights.push_back(scene::builtin::sunLight({1.0f, 2.0f, 1.5f}, 1.0f));
  scene::builtin::addObject(cube, "cube", scene::builtin::addMesh(cube, scene::parametricMesh("cube", roundedCube())),
                            scene::builtin::addMaterial(cube, scene::builtin::matte("grey", 0x808080)));
  // Close to a corner: the three faces in view are cut at different densities, each finer near the eye.
  cube.camera = {{1.9f, 1.5f, 2.3f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 60.0f};
  const auto scene = std::make_shared<const scene::Scene>(std::move(cube));
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  ASSERT_TRUE(rig.renderer);
  for (const float factor : {1.0f, 1.7f, 3.0f}) {
    const Tessellated view = tessellate(rig, movedAway(scene->camera, factor), 320, 240);
    ASSERT_GT(view.measure.triangles, 0u);
    const render::RenderedFrame& frame = view.frame;
    const auto background = [&](int x, int y) {
      const std::uint8_t* p = &frame.rgba[4 * (static_cast<std::size_t>(y) * frame.width + x)];
      return p[0] > 200 && p[1] < 60 && p[2] > 200;
    };
    // The cube is convex, so along any row or column its pixels are one unbroken run: a background
    // pixel between two of its pixels is a crack.
    std::size_t covered = 0, cracks = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const int lines = pass == 0 ? frame.height : frame.width, length = pass == 0 ? frame.width : frame.height;
      for (int line = 0; line < lines; ++line) {
        int first = -1, last = -1;
        std::vector<bool> isBackground(static_cast<std::size_t>(length));
        for (int i = 0; i < length; ++i) {
          isBackground[static_cast<std::size_t>(i)] = pass == 0 ? background(i, line) : background(line, i);
          if (isBackground[static_cast<std::size_t>(i)]) continue;
          if (first < 0) first = i;
          last = i;
          covered += pass == 0;
        }
        for (int i = first + 1; first >= 0 && i < last; ++i) cracks += isBackground[static_cast<std::size_t>(i)];
      }
    }
    std::printf("distance x%.1f: %zu triangles, %zu pixels covered, %zu crack pixels\n", factor, view.measure.triangles,
                covered, cracks);
    EXPECT_GT(covered, 1000u);
    EXPECT_EQ(cracks, 0u);
  }
}
