// After Szabo 2013, Figure 7: coarse and fine meshes side by side in one mirror ball, the case
// adaptive tessellation is for. The teapot is procedural (lathe body and lid, swept handle and
// spout), not the Utah teapot.
#include <cmath>
#include <vector>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"
#include "scene/builtin/Tube.h"

namespace specula::scene::builtin {

namespace {

// About 0.26 m tall, spout along +x, handle along −x, standing on y = 0.
Mesh teapotMesh() {
  constexpr int kSlices = 128;
  const glm::vec2 bodyCentre{0.0f, 0.09f}, bodyRadii{0.125f, 0.09f};
  Mesh teapot{"teapot", {}, {}};

  // Body: a flat foot (radius 0.07), an elliptical belly up to the lid opening (radius 0.062),
  // closed across underneath the lid.
  std::vector<glm::vec2> body{{0.0f, 0.0f}, {0.065f, 0.0f}};
  const auto belly = ellipseArc(bodyCentre, bodyRadii, -glm::degrees(std::acos(0.07f / bodyRadii.x)),
                                glm::degrees(std::acos(0.062f / bodyRadii.x)), 56);
  body.insert(body.end(), belly.begin(), belly.end());
  body.insert(body.end(), {{0.064f, 0.176f}, {0.058f, 0.178f}, {0.056f, 0.172f}, {0.0f, 0.172f}});
  primitives::append(teapot, primitives::lathe("teapot-body", body, kSlices), glm::mat4(1.0f));

  // Lid: a low dome sitting in the opening, topped by a round knob.
  std::vector<glm::vec2> lid{{0.0f, 0.17f}};
  const auto dome = ellipseArc({0.0f, 0.17f}, {0.06f, 0.035f}, 0.0f, 72.0f, 16);
  const auto knob = ellipseArc({0.0f, 0.222f}, glm::vec2(0.016f), -54.0f, 90.0f, 12);
  lid.insert(lid.end(), dome.begin(), dome.end());
  lid.insert(lid.end(), knob.begin(), knob.end());
  primitives::append(teapot, primitives::lathe("teapot-lid", lid, kSlices), glm::mat4(1.0f));

  // Handle: a torus segment on the −x side whose ends sink into the belly.
  primitives::append(teapot, arcHandle("teapot-handle", {-0.11f, 0.095f}, 0.05f, 60.0f, 300.0f, 0.009f),
                     glm::mat4(1.0f));

  // Spout: a quadratic Bézier from inside the belly, tapering to the tip.
  constexpr int kSpoutPoints = 36;
  const glm::vec3 p0{0.08f, 0.06f, 0.0f}, p1{0.18f, 0.07f, 0.0f}, p2{0.21f, 0.18f, 0.0f};
  std::vector<glm::vec3> spoutPath;
  std::vector<float> spoutRadii;
  for (int k = 0; k < kSpoutPoints; ++k) {
    const float t = static_cast<float>(k) / static_cast<float>(kSpoutPoints - 1);
    spoutPath.push_back((1 - t) * (1 - t) * p0 + 2 * (1 - t) * t * p1 + t * t * p2);
    spoutRadii.push_back(0.024f + (0.011f - 0.024f) * t);
  }
  primitives::append(teapot, tube("teapot-spout", spoutPath, spoutRadii, 24), glm::mat4(1.0f));
  return teapot;
}

// Few slices and few profile points on purpose: the coarse mesh the paper contrasts with the teapot.
Mesh candlestickMesh() {
  const std::vector<glm::vec2> profile{{0.0f, 0.0f},    {0.09f, 0.0f}, {0.09f, 0.015f}, {0.05f, 0.035f},
                                       {0.022f, 0.05f}, {0.02f, 0.2f}, {0.05f, 0.22f},  {0.055f, 0.235f},
                                       {0.02f, 0.24f},  {0.0f, 0.24f}};
  return primitives::lathe("candlestick", profile, 8);
}

}  // namespace

Scene teapotTableScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.12f);
  scene.background = srgbHex(0x1B1F2A);
  scene.lights.push_back(sunLight({0.5f, 1.0f, 0.7f}, 1.0f));
  scene.camera = {{0.3f, 0.75f, 1.6f}, {0.05f, 0.18f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};

  constexpr float kBallRadius = 0.3f;
  const std::uint32_t ball =
      addSphereMirror(scene, "mirror-ball", addMesh(scene, primitives::uvSphere("mirror-ball", kBallRadius, 96, 48)),
                      addMaterial(scene, perfectMirror("mirror")), kBallRadius, placed({0.0f, kBallRadius, 0.0f}));
  scene.objects[ball].reflected = false;  // the only mirror, and convex: it never shows itself

  // 3 × 2 m in six quads, printed with 6 × 4 gingham cells the mirror must bend.
  addObject(scene, "tablecloth", addMesh(scene, primitives::grid("tablecloth", 3.0f, 2.0f, 3, 2)),
            addMaterial(scene, checker("gingham", 0xF4F1EA, 0xB22222, 2.0f, false)));

  const glm::vec3 candlestickAt{-0.6f, 0.0f, -0.25f};
  addObject(scene, "candlestick", addMesh(scene, candlestickMesh()), addMaterial(scene, matte("brass", 0xB08D57)),
            placed(candlestickAt));
  addObject(scene, "candle", addMesh(scene, primitives::cylinder("candle", 0.018f, 0.2f, 8, true)),
            addMaterial(scene, matte("wax", 0xF3EEDC)), placed(candlestickAt + glm::vec3(0.0f, 0.24f, 0.0f)));
  addObject(scene, "flame", addMesh(scene, primitives::uvSphere("flame", 0.012f, 12, 6)),
            addMaterial(scene, emissive("flame", 0xFFC94A)),
            placed(candlestickAt + glm::vec3(0.0f, 0.455f, 0.0f), 0.0f, {1.0f, 1.8f, 1.0f}));

  const std::uint32_t teapot =
      addObject(scene, "teapot", addMesh(scene, teapotMesh()), addMaterial(scene, matte("porcelain", 0x5B7DB1)),
                placed({0.65f, 0.0f, -0.1f}, 30.0f));
  scene.animations.push_back({teapot, Spin{{0.0f, 1.0f, 0.0f}, 20.0}});
  return scene;
}

}  // namespace specula::scene::builtin
