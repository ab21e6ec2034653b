// The reference ray tracer's shading, bounce rule, visibility rules, errors and determinism, each on a
// small scene built here whose expected pixels follow from the documented formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "math/Color.h"
#include "reference/RayTracer.h"
#include "scene/Primitives.h"
#include "scene/ScenePose.h"

using namespace specula;

namespace {

// round(255 · sRGB(clamp(c))), restated from the GL sRGB8 framebuffer rule.
int srgbByte(double linear) {
  return static_cast<int>(std::lround(255.0 * math::linearToSrgb(static_cast<float>(std::clamp(linear, 0.0, 1.0)))));
}

scene::Material unlit(const glm::vec3& color, float reflectivity = 0.0f) {
  scene::Material m;
  m.baseColor = color;
  m.unlit = true;
  m.reflectivity = reflectivity;
  return m;
}

std::uint32_t add(scene::Scene& s, scene::Mesh mesh, const scene::Material& material, const glm::vec3& at,
                  bool mirror = false) {
  s.meshes.push_back(std::move(mesh));
  s.materials.push_back(material);
  scene::SceneObject object;
  object.name = s.meshes.back().name;
  object.mesh = static_cast<std::uint32_t>(s.meshes.size() - 1);
  object.material = static_cast<std::uint32_t>(s.materials.size() - 1);
  object.transform.translation = at;
  if (mirror) object.mirror.emplace();
  s.objects.push_back(std::move(object));
  return static_cast<std::uint32_t>(s.objects.size() - 1);
}

Result<reference::ReferenceImage> render(const scene::Scene& s, const math::Camera& camera,
                                         reference::RayTracerOptions options) {
  auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(s));
  if (!tracer) return Error{tracer.error()};
  scene::ScenePose pose = scene::ScenePose::at(s, 0.0);
  pose.camera = camera;
  return (*tracer)->render(pose, options);
}

const std::uint8_t* pixel(const reference::ReferenceImage& image, int column, int row) {
  return &image.rgba[(static_cast<std::size_t>(row) * image.width + column) * 4];
}

void expectPixelNear(const reference::ReferenceImage& image, int column, int row, const glm::dvec3& linear) {
  const std::uint8_t* p = pixel(image, column, row);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(p[c], srgbByte(linear[c]), 1) << "channel " << c << " of pixel (" << column << ", " << row << ")";
}

TEST(ReferenceShading, LambertWithAmbientDirectionalAndPointLightsLightsTheSideFacingTheViewer) {
  scene::Scene s;
  s.ambient = {0.05f, 0.06f, 0.07f};
  s.background = glm::vec3(0.0f);
  scene::Material matte;
  matte.baseColor = {0.6f, 0.4f, 0.2f};
  add(s, scene::primitives::grid("plane", 4.0f, 4.0f, 1, 1), matte, glm::vec3(0.0f));
  const glm::vec3 sun = glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f));
  s.lights = {{scene::Light::Kind::Directional, sun, {1.0f, 0.9f, 0.8f}, 0.8f},
              {scene::Light::Kind::Point, {0.5f, 1.5f, -0.3f}, {0.3f, 0.3f, 1.0f}, 1.2f},
              {scene::Light::Kind::Point, {-0.4f, -1.0f, 0.2f}, {1.0f, 0.5f, 0.5f}, 0.7f}};  // under the plane

  constexpr int kSize = 21;
  for (const double eyeY : {3.0, -3.0}) {
    SCOPED_TRACE(eyeY > 0 ? "from above" : "from below");
    const glm::dvec3 eye(0.3, eyeY, 0.2), target(0.1, 0.0, -0.1);
    auto image = render(s, {glm::vec3(eye), glm::vec3(target), {0.0f, 0.0f, -1.0f}, 30.0f}, {kSize, kSize, 1, 1});
    ASSERT_TRUE(image) << image.error();
    // The ray through each pixel centre, built here, meets the plane y = 0 well inside its edges.
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 0.0, -1.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(glm::radians(15.0));
    const glm::dvec3 facing(0.0, eyeY > 0 ? 1.0 : -1.0, 0.0);  // the plane's normal turned to the viewer
    for (int row = 0; row < kSize; row += 4)
      for (int column = 0; column < kSize; column += 4) {
        const double sx = (2.0 * (column + 0.5) / kSize - 1.0) * tanHalf,
                     sy = (1.0 - 2.0 * (row + 0.5) / kSize) * tanHalf;
        const glm::dvec3 d = glm::normalize(forward + sx * right + sy * up);
        const glm::dvec3 hit = eye - (eye.y / d.y) * d;
        glm::dvec3 light = glm::dvec3(s.ambient);
        for (const scene::Light& l : s.lights) {
          const glm::dvec3 toLight = l.kind == scene::Light::Kind::Directional
                                         ? glm::dvec3(l.vector)
                                         : glm::normalize(glm::dvec3(l.vector) - hit);
          light += glm::dvec3(l.color * l.intensity) * std::max(glm::dot(facing, toLight), 0.0);
        }
        expectPixelNear(*image, column, row, glm::dvec3(matte.baseColor) * light);
      }
  }
}

TEST(ReferenceShading, CheckerCellsFollowUvTimesCellsPerUnit) {
  scene::Scene s;
  scene::Material checker = unlit({0.9f, 0.9f, 0.9f});
  checker.checker = scene::Checker{{0.1f, 0.2f, 0.3f}, 2.0f};  // half-metre cells on the grid's metre uv
  add(s, scene::primitives::grid("plane", 4.0f, 4.0f, 1, 1), checker, glm::vec3(0.0f));
  // Looking straight down at (0.25, 0, 0.25): the centre of cell (0, 0), even; up is −z.
  constexpr int kSize = 16;
  auto image =
      render(s, {{0.25f, 2.0f, 0.25f}, {0.25f, 0.0f, 0.25f}, {0.0f, 0.0f, -1.0f}, 53.13f}, {kSize, kSize, 1, 1});
  ASSERT_TRUE(image) << image.error();
  // tan(53.13° / 2) · 2 m = 1 m: the image spans x and z in [−0.75, 1.25], 1/8 m per pixel.
  for (int row = 0; row < kSize; ++row)
    for (int column = 0; column < kSize; ++column) {
      const double x = -0.75 + (column + 0.5) / 8.0, z = -0.75 + (row + 0.5) / 8.0;
      const long cell = static_cast<long>(std::floor(2.0 * x)) + static_cast<long>(std::floor(2.0 * z));
      expectPixelNear(*image, column, row, glm::dvec3(cell % 2 == 0 ? checker.baseColor : checker.checker->oddColor));
    }
}

// Two parallel plane mirrors facing each other, the eye between them looking straight down at A:
// every bounce alternates between A and B. Three cells a side keep the centre ray off grid vertices.
scene::Scene hallOfMirrors(const glm::vec3& colorA, float reflectivityA, const glm::vec3& colorB, float reflectivityB) {
  scene::Scene s;
  add(s, scene::primitives::grid("A", 100.0f, 100.0f, 3, 3), unlit(colorA, reflectivityA), glm::vec3(0.0f), true);
  add(s, scene::primitives::grid("B", 100.0f, 100.0f, 3, 3), unlit(colorB, reflectivityB), {0.0f, 2.0f, 0.0f}, true);
  return s;
}

TEST(ReferenceBounces, MirrorsBlendByReflectivityAndTheLastBounceShowsTheSurfaceItself) {
  const glm::dvec3 colorA(0.8, 0.1, 0.1), colorB(0.1, 0.2, 0.9);
  const double rA = 0.6, rB = 0.7;
  const scene::Scene s =
      hallOfMirrors(glm::vec3(colorA), static_cast<float>(rA), glm::vec3(colorB), static_cast<float>(rB));
  // What a ray arriving at mirror `atA ? A : B` sees with `left` bounces left.
  const std::function<glm::dvec3(bool, int)> seen = [&](bool atA, int left) -> glm::dvec3 {
    const glm::dvec3 own = atA ? colorA : colorB;
    const double r = atA ? rA : rB;
    return left == 0 ? own : (1.0 - r) * own + r * seen(!atA, left - 1);
  };
  for (int bounces = 0; bounces <= 4; ++bounces) {
    SCOPED_TRACE(bounces);
    auto image = render(s, {{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 20.0f}, {5, 5, bounces, 1});
    ASSERT_TRUE(image) << image.error();
    expectPixelNear(*image, 2, 2, seen(true, bounces));
    EXPECT_EQ(image->mirrorMask[2 * 5 + 2], 1);
  }
}

TEST(ReferenceBounces, ObjectsNotReflectedAppearDirectlyButNotInMirrors) {
  scene::Scene s;
  add(s, scene::primitives::grid("floor mirror", 20.0f, 20.0f, 2, 2), unlit(glm::vec3(0.0f), 1.0f), glm::vec3(0.0f),
      true);
  const std::uint32_t box =
      add(s, scene::primitives::box("box", glm::vec3(1.0f)), unlit({0.0f, 1.0f, 0.0f}), {0.0f, 1.0f, 0.0f});
  const math::Camera camera{{0.0f, 3.0f, 6.0f}, {0.0f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}, 50.0f};
  // Green pixels inside and outside the mirror mask.
  const auto greenCounts = [&](const scene::Scene& scene) -> std::pair<int, int> {
    auto image = render(scene, camera, {64, 48, 1, 0});
    EXPECT_TRUE(image) << image.error();
    if (!image) return {-1, -1};
    int inMirror = 0, outside = 0;
    for (std::size_t i = 0; i < image->mirrorMask.size(); ++i)
      if (image->rgba[4 * i] == 0 && image->rgba[4 * i + 1] == 255 && image->rgba[4 * i + 2] == 0)
        ++(image->mirrorMask[i] ? inMirror : outside);
    return {inMirror, outside};
  };
  const auto [reflectedInMirror, reflectedOutside] = greenCounts(s);
  s.objects[box].reflected = false;
  const auto [hiddenInMirror, hiddenOutside] = greenCounts(s);
  EXPECT_GT(reflectedInMirror, 30);
  EXPECT_EQ(hiddenInMirror, 0);
  EXPECT_GT(reflectedOutside, 30);
  EXPECT_EQ(hiddenOutside, reflectedOutside);
}

TEST(ReferenceRayTracer, EmptySceneShowsTheBackgroundEverywhereWithAnEmptyMask) {
  scene::Scene s;
  s.background = {0.2f, 0.5f, 1.0f};
  auto image = render(s, math::Camera{}, {8, 6, 1, 0});
  ASSERT_TRUE(image) << image.error();
  ASSERT_EQ(image->rgba.size(), 8u * 6u * 4u);
  for (int row = 0; row < 6; ++row)
    for (int column = 0; column < 8; ++column) {
      expectPixelNear(*image, column, row, glm::dvec3(s.background));
      EXPECT_EQ(pixel(*image, column, row)[3], 255);
    }
  EXPECT_TRUE(std::all_of(image->mirrorMask.begin(), image->mirrorMask.end(), [](std::uint8_t m) { return m == 0; }));
}

TEST(ReferenceRayTracer, RefusesEmptyImagesNegativeBouncesAndDegenerateCameras) {
  const scene::Scene s = hallOfMirrors({1, 0, 0}, 0.5f, {0, 0, 1}, 0.5f);
  const math::Camera camera{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 20.0f};
  auto empty = render(s, camera, {0, 10, 1, 0});
  ASSERT_FALSE(empty);
  EXPECT_NE(empty.error().find("0x10"), std::string::npos) << empty.error();
  auto negative = render(s, camera, {10, 10, -1, 0});
  ASSERT_FALSE(negative);
  EXPECT_NE(negative.error().find("maxBounces"), std::string::npos) << negative.error();
  auto huge = render(s, camera, {1 << 16, 1 << 16, 1, 0});
  ASSERT_FALSE(huge);
  EXPECT_NE(huge.error().find("smaller"), std::string::npos) << huge.error();
  math::Camera degenerate = camera;
  degenerate.target = degenerate.eye;
  auto onTarget = render(s, degenerate, {10, 10, 1, 0});
  ASSERT_FALSE(onTarget);
  EXPECT_NE(onTarget.error().find("camera"), std::string::npos) << onTarget.error();
}

TEST(ReferenceRayTracer, ThreadCountDoesNotChangeAPixel) {
  const scene::Scene s = hallOfMirrors({0.8f, 0.1f, 0.1f}, 0.6f, {0.1f, 0.2f, 0.9f}, 0.7f);
  const math::Camera camera{{0.3f, 1.0f, 0.1f}, {2.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}, 70.0f};
  auto one = render(s, camera, {48, 32, 3, 1});
  auto three = render(s, camera, {48, 32, 3, 3});
  ASSERT_TRUE(one && three);
  EXPECT_EQ(one->rgba, three->rgba);
  EXPECT_EQ(one->mirrorMask, three->mirrorMask);
}

}  // namespace
