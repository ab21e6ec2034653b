// After Estalella et al. 2006 (their kitchen: one large metal bowl, ~15k vertices, the viewpoint
// moving towards the bowl). Coarse furniture and fine fruit, cup and bottle surround the bowl.
#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <vector>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"
#include "scene/builtin/Tube.h"

namespace specula::scene::builtin {

namespace {

constexpr float kTableTop = 0.76f;  // height of the table surface

// A closed thin steel shell: outer wall up from a flat foot, a rounded rim, inner wall back down.
// Outside it is convex, inside concave, hence a mixed-curvature mirror.
Mesh bowlMesh() {
  constexpr float kRadius = 0.15f, kHeight = 0.1f, kWall = 0.004f;
  std::vector<glm::vec2> profile{{0.0f, 0.0f}, {0.048f, 0.0f}};
  const auto outer =
      ellipseArc({0.0f, kHeight}, {kRadius, kHeight}, -glm::degrees(std::acos(0.05f / kRadius)), 0.0f, 28);
  const auto rim = ellipseArc({kRadius - kWall / 2, kHeight}, glm::vec2(kWall / 2), 0.0f, 180.0f, 7);
  const auto inner = ellipseArc({0.0f, kHeight}, {kRadius - kWall, kHeight - kWall}, 0.0f, -90.0f, 30);
  for (const auto* part : {&outer, &rim, &inner}) profile.insert(profile.end(), part->begin(), part->end());
  return primitives::lathe("bowl", profile, 72);
}

// A mug: a thin-walled lathe shell with a torus-segment handle whose ends sink into the wall.
Mesh cupMesh() {
  const std::vector<glm::vec2> shell{
      {0.0f, 0.0f},     {0.032f, 0.0f},    {0.034f, 0.003f},  {0.035f, 0.02f},    {0.036f, 0.04f},    {0.037f, 0.06f},
      {0.038f, 0.075f}, {0.039f, 0.088f},  {0.0395f, 0.09f},  {0.0385f, 0.0915f}, {0.0375f, 0.0908f}, {0.0368f, 0.088f},
      {0.0358f, 0.07f}, {0.0345f, 0.045f}, {0.0335f, 0.025f}, {0.033f, 0.012f},   {0.031f, 0.008f},   {0.0f, 0.008f}};
  Mesh cup = primitives::lathe("cup", shell, 48);
  primitives::append(cup, arcHandle("cup-handle", {0.048f, 0.05f}, 0.024f, -120.0f, 120.0f, 0.0045f), glm::mat4(1.0f));
  return cup;
}

Mesh bottleMesh() {
  std::vector<glm::vec2> profile{{0.0f, 0.0f}, {0.038f, 0.0f}, {0.04f, 0.004f}, {0.04f, 0.17f}};
  const auto shoulder = ellipseArc({0.013f, 0.17f}, {0.027f, 0.07f}, 0.0f, 90.0f, 14);
  profile.insert(profile.end(), shoulder.begin(), shoulder.end());
  profile.insert(profile.end(), {{0.013f, 0.29f}, {0.015f, 0.292f}, {0.015f, 0.3f}, {0.0f, 0.3f}});
  return primitives::lathe("bottle", profile, 48);
}

// Narrow at the stalk, wide at the base: radius follows sqrt(sin πt) tapered towards the top.
Mesh pearMesh() {
  constexpr int kPoints = 26;
  std::vector<glm::vec2> profile;
  for (int k = 0; k < kPoints; ++k) {
    const float t = static_cast<float>(k) / static_cast<float>(kPoints - 1);
    profile.push_back(
        {0.042f * std::sqrt(std::max(0.0f, std::sin(glm::pi<float>() * t))) * (1.0f - 0.5f * t), 0.11f * t});
  }
  return primitives::lathe("pear", profile, 32);
}

// The top surface is a grid of ~10 cm cells (Estalella's loader subdivided large geometry too): the
// bowl's outer wall reflects the table all round its foot, where a coarse top has no vertex at all.
// An odd number of cells each way puts the bowl at a cell's centre, so no vertex lies under its foot.
Mesh tableMesh() {
  Mesh table{"table", {}, {}};
  Mesh slab = primitives::box("table-top", {1.6f, 0.04f, 0.9f});
  std::vector<std::uint32_t> sidesAndBottom;
  for (std::size_t t = 0; t < slab.triangleCount(); ++t)
    if (slab.vertices[slab.indices[3 * t]].normal.y < 0.5f)
      sidesAndBottom.insert(sidesAndBottom.end(), slab.indices.begin() + 3 * t, slab.indices.begin() + 3 * t + 3);
  slab.indices = std::move(sidesAndBottom);
  primitives::append(table, slab, placed({0.0f, kTableTop - 0.02f, 0.0f}).matrix());
  primitives::append(table, primitives::grid("table-surface", 1.6f, 0.9f, 15, 9),
                     placed({0.0f, kTableTop, 0.0f}).matrix());
  for (const float x : {-0.72f, 0.72f})
    for (const float z : {-0.38f, 0.38f})
      primitives::append(table, primitives::box("table-leg", {0.05f, kTableTop - 0.04f, 0.05f}),
                         placed({x, (kTableTop - 0.04f) / 2, z}).matrix());
  return table;
}

// Seat, back and four legs; the chair faces +z in object space.
Mesh chairMesh() {
  Mesh chair{"chair", {}, {}};
  primitives::append(chair, primitives::box("seat", {0.42f, 0.04f, 0.42f}), placed({0.0f, 0.45f, 0.0f}).matrix());
  primitives::append(chair, primitives::box("back", {0.42f, 0.45f, 0.03f}), placed({0.0f, 0.69f, -0.195f}).matrix());
  for (const float x : {-0.18f, 0.18f})
    for (const float z : {-0.18f, 0.18f})
      primitives::append(chair, primitives::box("leg", {0.035f, 0.43f, 0.035f}), placed({x, 0.215f, z}).matrix());
  return chair;
}

}  // namespace

Scene kitchenScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.1f);
  scene.background = srgbHex(0x2A2E36);
  scene.lights.push_back(sunLight({-0.4f, 1.0f, 0.6f}, 0.9f));
  scene.lights.push_back(sunLight({0.7f, 0.5f, -0.2f}, 0.3f));

  // The room: a tiled floor, two walls, counters and a fridge, all coarse.
  addObject(scene, "floor", addMesh(scene, primitives::grid("kitchen-floor", 5.0f, 5.0f, 10, 10)),
            addMaterial(scene, checker("floor-tiles", 0xD8D2C4, 0x8C7B6B, 2.0f, false)));
  const std::uint32_t plaster = addMaterial(scene, matte("plaster", 0xE9E4D8));
  const glm::quat facingPlusZ = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));
  const glm::quat facingPlusX = glm::angleAxis(-glm::half_pi<float>(), glm::vec3(0, 0, 1));
  addObject(scene, "back-wall", addMesh(scene, primitives::grid("back-wall", 5.0f, 3.0f, 5, 3)), plaster,
            {{0.0f, 1.5f, -2.5f}, facingPlusZ, glm::vec3(1.0f)});
  addObject(scene, "side-wall", addMesh(scene, primitives::grid("side-wall", 3.0f, 5.0f, 3, 5)), plaster,
            {{-2.5f, 1.5f, 0.0f}, facingPlusX, glm::vec3(1.0f)});

  const std::uint32_t unitBox = addMesh(scene, primitives::box("unit-box", glm::vec3(1.0f)));
  const std::uint32_t cabinet = addMaterial(scene, matte("cabinet", 0x6E8FA6));
  addObject(scene, "base-cabinets", unitBox, cabinet, placed({0.2f, 0.43f, -2.2f}, 0.0f, {2.4f, 0.86f, 0.6f}));
  addObject(scene, "countertop", unitBox, addMaterial(scene, matte("countertop", 0x3A3A3A)),
            placed({0.2f, 0.88f, -2.18f}, 0.0f, {2.5f, 0.04f, 0.64f}));
  addObject(scene, "wall-cabinets", unitBox, cabinet, placed({0.2f, 1.85f, -2.32f}, 0.0f, {2.4f, 0.7f, 0.35f}));
  addObject(scene, "fridge", unitBox, addMaterial(scene, matte("fridge", 0xF0F0EE)),
            placed({-1.9f, 0.9f, -2.15f}, 0.0f, {0.7f, 1.8f, 0.65f}));

  const std::uint32_t wood = addMaterial(scene, matte("wood", 0x8B5A2B));
  addObject(scene, "table", addMesh(scene, tableMesh()), wood);
  const std::uint32_t chair = addMesh(scene, chairMesh());
  addObject(scene, "chair-front", chair, wood, placed({0.1f, 0.0f, 0.75f}, 180.0f));
  addObject(scene, "chair-side", chair, wood, placed({1.15f, 0.0f, -0.05f}, -90.0f));
  addObject(scene, "cutting-board", unitBox, addMaterial(scene, matte("board", 0xC8A165)),
            placed({-0.55f, kTableTop + 0.01f, 0.12f}, 10.0f, {0.4f, 0.02f, 0.26f}));

  // The reflector: polished steel, closed because the shell has an outside and an inside.
  const std::uint32_t bowl =
      addObject(scene, "bowl", addMesh(scene, bowlMesh()), addMaterial(scene, mirror("steel", 0x9AA0A8, 0.85f)),
                placed({0.0f, kTableTop, 0.0f}));
  scene.objects[bowl].mirror = MirrorInfo{MirrorCurvature::Mixed, true, std::nullopt, std::nullopt, std::nullopt};

  // Fine objects, kept clear of the circle the orbiting apple sweeps (radius 0.31 about the bowl).
  const std::uint32_t fruitSphere = addMesh(scene, primitives::uvSphere("fruit", 1.0f, 40, 20));
  const std::uint32_t apple = addMaterial(scene, matte("apple", 0xB3261E));
  const std::uint32_t orange = addMaterial(scene, matte("orange", 0xF28C28));
  const auto fruit = [&](const char* name, std::uint32_t material, const glm::vec3& base, const glm::vec3& radii) {
    return addObject(scene, name, fruitSphere, material, placed(base + glm::vec3(0.0f, radii.y, 0.0f), 0.0f, radii));
  };
  const std::uint32_t orbitingApple = fruit("apple-orbiting", apple, {0.27f, kTableTop, 0.0f}, {0.04f, 0.036f, 0.04f});
  fruit("apple-board", apple, {-0.62f, kTableTop + 0.02f, 0.16f}, {0.04f, 0.036f, 0.04f});
  fruit("orange-1", orange, {0.42f, kTableTop, 0.25f}, glm::vec3(0.045f));
  fruit("orange-2", orange, {0.5f, kTableTop, 0.11f}, glm::vec3(0.043f));
  fruit("lemon", addMaterial(scene, matte("lemon", 0xF2D43D)), {-0.47f, kTableTop + 0.02f, 0.07f},
        {0.04f, 0.03f, 0.03f});
  addObject(scene, "pear", addMesh(scene, pearMesh()), addMaterial(scene, matte("pear", 0xB5C13A)),
            placed({0.22f, kTableTop, -0.32f}));
  addObject(scene, "cup", addMesh(scene, cupMesh()), addMaterial(scene, matte("mug", 0xF5F0E6)),
            placed({0.45f, kTableTop, -0.12f}, -60.0f));
  addObject(scene, "bottle", addMesh(scene, bottleMesh()), addMaterial(scene, matte("bottle-glass", 0x2E6B3A)),
            placed({-0.2f, kTableTop, -0.33f}));

  scene.animations.push_back({orbitingApple, Orbit{{0.0f, kTableTop, 0.0f}, {0.0f, 1.0f, 0.0f}, 25.0}});

  // The viewpoint moves in towards the bowl until it fills much of the view, then back out.
  const glm::vec3 bowlCentre{0.0f, kTableTop + 0.05f, 0.0f};
  const math::Camera far{{1.6f, 1.6f, 2.2f}, bowlCentre, {0.0f, 1.0f, 0.0f}, 45.0f};
  const math::Camera near{{0.35f, kTableTop + 0.35f, 0.5f}, bowlCentre, {0.0f, 1.0f, 0.0f}, 45.0f};
  scene.camera = far;
  scene.animations.push_back({std::nullopt, CameraPath{{{0.0, far}, {10.0, near}, {20.0, far}}, true}});
  return scene;
}

}  // namespace specula::scene::builtin
