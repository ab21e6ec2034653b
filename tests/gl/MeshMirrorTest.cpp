// Mesh mirrors, the general case (no analytic shape: the search, refinement, hidden-vertex rule and
// reflection all run on the mesh), each rendered and compared with the Embree ray tracer tracing the
// same mesh. Before mesh mirrors were fixed these scenes were 30-90 % wrong.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "bench/ReflectionAccuracy.h"
#include "encode/PngEncoder.h"
#include "gl/GlContext.h"
#include "SceneRig.h"
#include "render/Renderer.h"
#include "scene/Primitives.h"
#include "scene/SceneLoader.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"

using namespace specula;

namespace {

constexpr int kWidth = 640, kHeight = 480;

struct Comparison {
  double mismatch = 1.0;  // share of the reference's mirror pixels that differ strongly
  std::size_t mirrorPixels = 0;
  render::RenderedFrame frame;
};

// With SPECULA_TEST_IMAGES=folder, the frame and the reference are written there to look at.
void saveForLooking(const std::vector<std::uint8_t>& rgba, const std::string& suffix) {
  const char* folder = std::getenv("SPECULA_TEST_IMAGES");
  if (!folder) return;
  const std::string name =
      std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" + suffix + ".png";
  auto png = encode::encodePng({rgba.data(), kWidth, kHeight});
  if (png)
    std::ofstream(std::filesystem::path(folder) / name, std::ios::binary)
        .write(reinterpret_cast<const char*>(png->data()), static_cast<std::streamsize>(png->size()));
}

// Renders `scene` at `pose` and compares it with the ray tracer's image of `truth` (the same scene
// unless a test compares against an exact surface). By default the general path alone: every
// mirror searched, however small on screen, and drawn by its virtual objects only.
Comparison compare(const std::shared_ptr<const scene::Scene>& scene, const scene::ScenePose& pose,
                   const std::shared_ptr<const scene::Scene>& truth = nullptr,
                   const passes::ReflectionSettings& settings = specula::testing::virtualObjects()) {
  Comparison result;
  specula::testing::Rig rig = specula::testing::makeRig(scene);
  if (!rig.renderer) return result;
  auto frame = rig.renderer->render(pose, kWidth, kHeight, settings);
  EXPECT_TRUE(frame) << frame.error();
  if (!frame) return result;
  specula::testing::MirrorMismatch mismatch =
      specula::testing::mismatchAgainstRayTracer(truth ? truth : scene, pose, *frame);
  saveForLooking(frame->rgba, "search");
  if (!mismatch.reference.empty()) saveForLooking(mismatch.reference, "raytrace");
  result.mismatch = mismatch.share;
  result.mirrorPixels = mismatch.mirrorPixels;
  result.frame = std::move(*frame);
  return result;
}

std::shared_ptr<const scene::Scene> parse(const std::string& json, const std::filesystem::path& base = ".") {
  auto scene = scene::parseScene(json, base, "test scene");
  EXPECT_TRUE(scene) << scene.error();
  return scene ? std::make_shared<const scene::Scene>(std::move(*scene)) : nullptr;
}

// A mirror mesh over a checker floor with three coloured boxes around it; `mirrorMesh` is a mesh
// entry's JSON and `mirror` the object's extra keys.
std::string mirrorOverFloor(const std::string& mirrorMesh, const std::string& mirror, const std::string& camera) {
  return R"({"specula_scene": 1, "ambient": [0.1, 0.1, 0.1], "background": "#203040", "camera": )" + camera + R"(,
    "meshes": [)" +
         mirrorMesh + R"(,
      {"name": "floor", "primitive": {"type": "grid", "size": [16, 16], "cells": [16, 16]}},
      {"name": "box", "primitive": {"type": "box", "size": [0.6, 0.6, 0.6]}}],
    "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9},
      {"name": "checker", "color": "#e6e6e6", "unlit": true, "checker": {"color": "#191919", "cells_per_unit": 1}},
      {"name": "red", "color": "#d02020"}, {"name": "green", "color": "#20b040"}, {"name": "blue", "color": "#3050e0"}],
    "objects": [{"name": "mirror", "mesh": "mirror", "material": "chrome", )" +
         mirror + R"(},
      {"name": "floor", "mesh": "floor", "material": "checker", "translation": [0, -1, 0]},
      {"name": "red", "mesh": "box", "material": "red", "translation": [2.2, -0.7, 0.5]},
      {"name": "green", "mesh": "box", "material": "green", "translation": [-1.8, -0.7, 1.6]},
      {"name": "blue", "mesh": "box", "material": "blue", "translation": [0.3, -0.7, -2.4]}],
    "lights": [{"type": "directional", "direction": [1, 3, 2], "intensity": 0.9}]})";
}

const std::string kCameraAbove = R"({"eye": [1, 3, 3.5], "target": [0, -0.3, 0], "fov": 40})";

scene::ScenePose restPose(const scene::Scene& scene) { return scene::ScenePose::at(scene, 0.0); }

}  // namespace

// The general path under both searches, held to the same bounds.
class MeshMirrorSearch : public ::testing::TestWithParam<passes::SearchStrategy> {};

// The issue's first measurement: checker-sphere with a 128×64 mesh instead of the declared sphere.
TEST_P(MeshMirrorSearch, TessellatedSphereMatchesTheRayTracerAndTheExactSphere) {
  auto mesh = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("mesh-sphere"));
  auto exact = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("checker-sphere"));
  for (double t : {0.0, 4.0, 11.0}) {  // the camera orbits 20° a second
    const scene::ScenePose pose = scene::ScenePose::at(*mesh, t);
    const Comparison own = compare(mesh, pose, nullptr, specula::testing::withSearch(GetParam()));
    const Comparison sphere = compare(mesh, pose, exact, specula::testing::withSearch(GetParam()));
    std::printf(
        "mesh sphere t=%.0f, %s search: %.2f %% against its own ray trace, %.2f %% against the exact sphere's\n", t,
        passes::searchStrategyName(GetParam()), 100.0 * own.mismatch, 100.0 * sphere.mismatch);
    EXPECT_GT(own.mirrorPixels, 20000u);
    EXPECT_LE(own.mismatch, 0.015) << "t=" << t;     // 47-52 % before the fix
    EXPECT_LE(sphere.mismatch, 0.015) << "t=" << t;  // the issue's bound against the exact sphere
  }
}

// The issue's bound for the general case: the 128×64 mesh's reflection points within 0.5 px p99 of
// the exact sphere solver's, along the scene's orbit.
TEST_P(MeshMirrorSearch, TessellatedSphereReflectionPointsStayWithinHalfAPixel) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  ASSERT_TRUE(context) << context.error();
  auto renderer = render::Renderer::create(
      **context, std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("mesh-sphere")));
  ASSERT_TRUE(renderer) << renderer.error();
  for (double t : {0.0, 4.0, 11.0}) {
    const scene::ScenePose pose = scene::ScenePose::at((*renderer)->scene(), t);
    auto frame = (*renderer)->render(pose, kWidth, kHeight, specula::testing::withSearch(GetParam()));
    ASSERT_TRUE(frame) << frame.error();
    const auto errors = bench::measureReflectionPoints(**renderer, pose, *frame);
    ASSERT_GT(errors.pixels.size(), 100u);
    std::printf(
        "mesh sphere t=%.0f, %s search: reflection points p50 %.3f px, p99 %.3f px, max %.3f px over %zu vertices\n", t,
        passes::searchStrategyName(GetParam()), errors.percentile(0.5), errors.percentile(0.99), errors.percentile(1.0),
        errors.pixels.size());
    EXPECT_LE(errors.percentile(0.99), 0.5) << "t=" << t;
  }
}

TEST(MeshMirror, TessellatedEllipsoid) {
  auto scene = parse(mirrorOverFloor(
      R"({"name": "mirror", "primitive": {"type": "sphere", "radius": 1, "slices": 96, "stacks": 48}})",
      R"("scale": [1.4, 0.7, 0.9], "reflected": false, "mirror": {"curvature": "convex"})", kCameraAbove));
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("mesh ellipsoid: %.2f %% of %zu mirror pixels\n", 100.0 * result.mismatch, result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 10000u);
  EXPECT_LE(result.mismatch, 0.015);
}

// Mixed curvature found from the mesh: a convex outside and a saddle-shaped inside, each its own
// part; the torus also sees itself (its inner ring reflects its far side).
TEST(MeshMirror, TorusSplitIntoConvexAndSaddleParts) {
  auto scene = parse(
      mirrorOverFloor(R"({"name": "mirror", "primitive": {"type": "torus", "major_radius": 1, "minor_radius": 0.35,
                                         "major_segments": 96, "minor_segments": 48}})",
                      R"("rotation": {"axis": [1, 0, 0], "degrees": 60}, "mirror": {})",
                      R"({"eye": [0.5, 2.5, 3.2], "target": [0, -0.2, 0], "fov": 45})"));
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("mesh torus: %.2f %% of %zu mirror pixels\n", 100.0 * result.mismatch, result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 10000u);
  EXPECT_LE(result.mismatch, 0.05);  // thin bands at grazing silhouettes remain (measured 4.0 %)
}

// A large thin-shell bowl seen from above: its inside is concave (beyond the focal region objects
// appear upside down), its rim and far wall reflect in it, and its outside is convex.
TEST(MeshMirror, ConcaveBowlSeenFromInsideShowsItselfWhereItsRaysMeetIt) {
  auto scene = parse(mirrorOverFloor(R"({"name": "mirror", "primitive": {"type": "lathe", "slices": 96, "profile": [
                                           [0, 0], [0.4, 0], [0.62, 0.03], [0.82, 0.1], [0.97, 0.22], [1.1, 0.4], [1.16, 0.55],
                                           [1.2, 0.7], [1.19, 0.72], [1.15, 0.7], [1.11, 0.56], [1.05, 0.42], [0.93, 0.25],
                                           [0.79, 0.13], [0.6, 0.06], [0.4, 0.035], [0, 0.035]]}})",
                                     R"("translation": [0, -1, 0], "mirror": {})",
                                     R"({"eye": [0.4, 2.2, 1.6], "target": [0, -0.7, 0], "fov": 50})"));
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("concave bowl from inside: %.2f %% of %zu mirror pixels\n", 100.0 * result.mismatch, result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 30000u);
  EXPECT_LE(result.mismatch, 0.01);
}

// The kitchen's thin steel bowl, mixed curvature, reflected in itself: 51 % off before the fix.
TEST_P(MeshMirrorSearch, KitchenBowl) {
  auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("kitchen"));
  for (double t : {0.0, 1.0}) {
    const Comparison result =
        compare(scene, scene::ScenePose::at(*scene, t), nullptr, specula::testing::withSearch(GetParam()));
    std::printf("kitchen bowl t=%.0f, %s search: %.2f %% of %zu mirror pixels\n", t,
                passes::searchStrategyName(GetParam()), 100.0 * result.mismatch, result.mirrorPixels);
    EXPECT_GT(result.mirrorPixels, 1000u);
    EXPECT_LE(result.mismatch, 0.05) << "t=" << t;  // measured 3.1 % and 2.4 %; its rim is 2-4 pixels wide
  }
}

INSTANTIATE_TEST_SUITE_P(MeshMirror, MeshMirrorSearch, ::testing::ValuesIn(specula::testing::kSearchStrategies),
                         [](const auto& test) { return specula::testing::searchName(test.param); });

// Where a reflected image is squeezed against a silhouette or rim, its virtual triangles can leave
// pixels uncovered, which then showed the background: the kitchen bowl's rim and foot, the mesh
// sphere's outline. By default those pixels are ray-cast when their reflected ray meets some
// reflected object's bounds; rays that meet none (the sky in the sphere) are left alone.
TEST(MeshMirror, PixelsTheVirtualObjectsLeaveUncoveredAreRayCast) {
  passes::ReflectionSettings filled = specula::testing::virtualObjects();
  filled.rayCastUncovered = true;
  struct Case {
    const char* scene;
    double time;
    double bound;  // mirror mismatch with the uncovered pixels ray-cast
  };
  for (const Case& c : {Case{"kitchen", 0.0, 0.015}, Case{"kitchen", 1.0, 0.015}, Case{"mesh-sphere", 0.0, 0.001}}) {
    auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(c.scene));
    const scene::ScenePose pose = scene::ScenePose::at(*scene, c.time);
    const Comparison alone = compare(scene, pose);
    const Comparison withRays = compare(scene, pose, nullptr, filled);
    std::size_t rayCast = 0;
    for (const render::MirrorPlanSummary& part : withRays.frame.plan) rayCast += part.uncoveredRayCast;
    std::printf("%s t=%.0f: %.2f %% of %zu mirror pixels with %zu uncovered pixels ray-cast, %.2f %% without\n",
                c.scene, c.time, 100.0 * withRays.mismatch, withRays.mirrorPixels, rayCast, 100.0 * alone.mismatch);
    EXPECT_LE(withRays.mismatch, c.bound) << c.scene << " t=" << c.time;
    EXPECT_LT(withRays.mismatch, 0.5 * alone.mismatch) << c.scene << " t=" << c.time;
    EXPECT_GT(rayCast, 0u);
    EXPECT_LT(rayCast, withRays.mirrorPixels / 10) << "only rays that can meet a reflected object are cast";
  }
}

// A G-buffer point between texels (another scale) or rounded to half floats lies a little off the
// surface; the bowl's ray cast against itself then met its own outer wall where it starts, and
// speckled its outside with its own colour (35 % at x2, 44 % at x0.5, 23 % in RGBA16F).
TEST(MeshMirror, TheKitchenBowlSeeingItselfStaysRightAtOtherGBufferScalesAndPrecision) {
  auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("kitchen"));
  const scene::ScenePose pose = scene::ScenePose::at(*scene, 0.0);
  struct Case {
    float scale;
    passes::GBufferPrecision precision;
    double bound;
  };
  for (const Case& c :
       {Case{2.0f, passes::GBufferPrecision::Float32, 0.10}, Case{0.5f, passes::GBufferPrecision::Float32, 0.18},
        Case{1.0f, passes::GBufferPrecision::Float16, 0.06}}) {
    passes::ReflectionSettings settings = specula::testing::virtualObjects();
    settings.gbufferScale = c.scale;
    settings.gbufferPrecision = c.precision;
    const Comparison result = compare(scene, pose, nullptr, settings);
    std::printf("kitchen bowl, G-buffer x%g %s: %.2f %% of %zu mirror pixels\n", c.scale,
                c.precision == passes::GBufferPrecision::Float16 ? "RGBA16F" : "RGBA32F", 100.0 * result.mismatch,
                result.mirrorPixels);
    EXPECT_LE(result.mismatch, c.bound) << "x" << c.scale;
  }
}

// Estalella's open mirror: a dome with no bottom, searched on its closed twin (the whole sphere).
TEST(MeshMirror, OpenDomeSearchedOnItsClosedTwin) {
  // The upper half of the twin's own profile (48 stacks), so the twin is the dome where it is seen.
  std::string profile;
  for (int k = 0; k <= 24; ++k) {
    const double angle = M_PI / 2 * k / 24;
    profile += (k ? ", [" : "[") + std::to_string(std::cos(angle)) + ", " + std::to_string(std::sin(angle)) + "]";
  }
  const std::string json =
      R"({"specula_scene": 1, "ambient": [0.1, 0.1, 0.1], "camera": {"eye": [1.5, 2.6, 3.2], "target": [0, -0.4, 0], "fov": 45},
    "meshes": [{"name": "dome", "primitive": {"type": "lathe", "slices": 96, "profile": [)" +
      profile + R"(]}},
      {"name": "ball", "primitive": {"type": "sphere", "radius": 1, "slices": 96, "stacks": 48}},
      {"name": "floor", "primitive": {"type": "grid", "size": [16, 16], "cells": [16, 16]}},
      {"name": "box", "primitive": {"type": "box", "size": [0.6, 0.6, 0.6]}}],
    "materials": [{"name": "chrome", "color": "#101010", "reflectivity": 0.9},
      {"name": "checker", "color": "#e6e6e6", "unlit": true, "checker": {"color": "#191919", "cells_per_unit": 1}},
      {"name": "red", "color": "#d02020"}],
    "objects": [{"name": "dome", "mesh": "dome", "material": "chrome", "translation": [0, -0.6, 0], "reflected": false,
                 "mirror": {"curvature": "convex", "closed": false, "closed_twin": "ball"}},
      {"name": "floor", "mesh": "floor", "material": "checker", "translation": [0, -1.001, 0]},
      {"name": "red", "mesh": "box", "material": "red", "translation": [2, -0.7, 0.5]}]})";
  auto scene = parse(json);
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("open dome on its closed twin: %.2f %% of %zu mirror pixels\n", 100.0 * result.mismatch,
              result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 20000u);
  EXPECT_LE(result.mismatch, 0.015);
}

// An imported OBJ mirror with its own normals (a smooth blob written here, loaded through a scene file).
TEST(MeshMirror, ImportedObjWithItsOwnNormals) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "specula-mesh-mirror-test";
  std::filesystem::create_directories(folder);
  const scene::Mesh blob = scene::primitives::uvSphere("blob", 1.0f, 80, 40);
  {
    std::ofstream obj(folder / "blob.obj");
    for (const scene::Vertex& v : blob.vertices) {
      // A squashed, bulging sphere: the OBJ's own normals are the analytic ones of this surface.
      const glm::vec3 p = v.position * glm::vec3(1.2f, 0.8f, 1.0f) * (1.0f + 0.1f * v.position.y);
      obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
    for (const scene::Vertex& v : blob.vertices) {
      // Normal of the map p = s(y) D x with D = diag(1.2, 0.8, 1), s = 1 + 0.1 y, by its inverse transpose.
      const glm::vec3 x = v.position;
      const float s = 1.0f + 0.1f * x.y;
      const glm::mat3 jacobian = glm::mat3(
          glm::vec3(1.2f * s, 0, 0), glm::vec3(0.12f * x.x, 0.8f * s + 0.08f * x.y, 0.1f * x.z), glm::vec3(0, 0, s));
      const glm::vec3 n = glm::normalize(glm::transpose(glm::inverse(jacobian)) * v.normal);
      obj << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
    }
    for (std::size_t t = 0; t < blob.triangleCount(); ++t) {
      obj << 'f';
      for (int k = 0; k < 3; ++k) obj << ' ' << blob.indices[3 * t + k] + 1 << "//" << blob.indices[3 * t + k] + 1;
      obj << '\n';
    }
  }
  auto scene = parse(
      mirrorOverFloor(R"({"name": "mirror", "file": "blob.obj"})", R"("reflected": false, "mirror": {})", kCameraAbove),
      folder);
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("imported OBJ mirror: %.2f %% of %zu mirror pixels\n", 100.0 * result.mismatch, result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 20000u);
  EXPECT_LE(result.mismatch, 0.015);
  std::filesystem::remove_all(folder);
}

namespace {

// A mesh mirror the sphere's hard cases (HardCasesTest) do not reach.
struct MirrorKind {
  const char* name;
  std::string mesh, placement;  // mirrorOverFloor()'s mesh entry and object keys
};

// A bicubic patch on the saddle y = 0.35 x z: a bilinear surface, whose control net lies on it.
std::string saddlePatch() {
  std::string points;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double x = -1.2 + 0.8 * i, z = -1.2 + 0.8 * j;
      points += (points.empty() ? "[" : ", [") + std::to_string(x) + ", " + std::to_string(0.35 * x * z) + ", " +
                std::to_string(z) + "]";
    }
  return R"({"name": "mirror", "segments": 24, "bezier_patches": [[)" + points + "]]}";
}

std::vector<MirrorKind> mirrorKinds() {
  return {
      {"torus", R"({"name": "mirror", "primitive": {"type": "torus", "major_radius": 1, "minor_radius": 0.35,
                   "major_segments": 96, "minor_segments": 48}})",
       R"("rotation": {"axis": [1, 0, 0], "degrees": 60}, "mirror": {})"},
      {"concave_bowl", R"({"name": "mirror", "primitive": {"type": "lathe", "slices": 96, "profile": [
                          [0, 0], [0.4, 0], [0.62, 0.03], [0.82, 0.1], [0.97, 0.22], [1.1, 0.4], [1.16, 0.55],
                          [1.2, 0.7], [1.19, 0.72], [1.15, 0.7], [1.11, 0.56], [1.05, 0.42], [0.93, 0.25],
                          [0.79, 0.13], [0.6, 0.06], [0.4, 0.035], [0, 0.035]]}})",
       R"("translation": [0, -0.9, 0], "mirror": {})"},
      {"saddle_patch", saddlePatch(), R"("translation": [0, -0.2, 0], "mirror": {})"},
  };
}

struct HardView {
  const char* name;
  const char* camera;
};

const HardView kHardViews[] = {
    {"grazing", R"({"eye": [4.5, -0.45, 0.8], "target": [0, -0.55, 0], "fov": 40})"},
    {"far", R"({"eye": [30, 24, 36], "target": [0, -0.3, 0], "fov": 40})"},
    {"half_off_screen", R"({"eye": [1, 3, 3.5], "target": [1.7, -0.3, 0], "fov": 40})"},
};

struct HardViewCase {
  int kind, view;  // into mirrorKinds() and kHardViews
  double bound;    // mirror mismatch against the ray tracer (measured on llvmpipe in the comment)
};

// The saddle patch seen grazing is not here: 59 % of its pixels are wrong (docs/hard-cases.md, "Known limits").
const HardViewCase kHardViewCases[] = {
    {0, 0, 0.003},  // torus: 0.14 % of 30 720 mirror pixels
    {0, 1, 0.045},  // 2.9 % of 625
    {0, 2, 0.065},  // 4.6 % of 63 935: thin bands at grazing silhouettes, as in TorusSplitIntoConvexAndSaddleParts
    {1, 0, 0.006},  // concave bowl: 0.36 % of 20 161
    {1, 1, 0.03},   // 1.6 % of 430
    {1, 2, 0.006},  // 0.38 % of 55 930
    {2, 1, 0.065},  // saddle patch: 4.2 % of 403
    {2, 2, 0.035},  // 2.3 % of 54 566
};

}  // namespace

class MeshMirrorHardViews : public ::testing::TestWithParam<HardViewCase> {};

// Each mirror kind searched from a grazing eye, from far away (the mirror a few dozen pixels
// across) and half off the screen, against the ray tracer tracing the same mesh.
TEST_P(MeshMirrorHardViews, SearchedMirrorsStayNearTheRayTracer) {
  const HardViewCase& hard = GetParam();
  const MirrorKind kind = mirrorKinds()[static_cast<std::size_t>(hard.kind)];
  const HardView& view = kHardViews[hard.view];
  auto scene = parse(mirrorOverFloor(kind.mesh, kind.placement, view.camera));
  ASSERT_TRUE(scene);
  const Comparison result = compare(scene, restPose(*scene));
  std::printf("%s %s: %.3f %% of %zu mirror pixels\n", kind.name, view.name, 100.0 * result.mismatch,
              result.mirrorPixels);
  EXPECT_GT(result.mirrorPixels, 200u);
  EXPECT_GT(result.frame.search.searched, 0u) << "searched, not cast";
  EXPECT_LE(result.mismatch, hard.bound);
}

INSTANTIATE_TEST_SUITE_P(MeshMirror, MeshMirrorHardViews, ::testing::ValuesIn(kHardViewCases), [](const auto& test) {
  return std::string(mirrorKinds()[static_cast<std::size_t>(test.param.kind)].name) + "_" +
         kHardViews[test.param.view].name;
});
