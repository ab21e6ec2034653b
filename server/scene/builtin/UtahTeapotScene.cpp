// The chrome Utah teapot (Newell's 32 Bézier patches, issue #19): a parametric mirror of mixed
// curvature (convex belly, saddle-shaped handle and spout, a knob with a neck) on a checker floor
// among coloured objects. Its own units: the floor's cells are one teapot unit wide.
#include "scene/ParametricMesh.h"
#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"
#include "scene/builtin/UtahTeapot.h"

namespace specula::scene::builtin {

Scene utahTeapotScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.1f);
  scene.background = srgbHex(0x3A4A66);
  // About 9 units from the teapot with a 40° field of view: it fills about half the frame's height.
  scene.camera = {{6.0f, 4.4f, 6.4f}, {0.0f, 1.4f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
  scene.lights.push_back(sunLight({0.4f, 1.0f, 0.6f}, 1.0f));

  const std::uint32_t teapot = addObject(scene, "teapot", addMesh(scene, parametricMesh("teapot", utahTeapotPatches())),
                                         addMaterial(scene, perfectMirror("chrome")));
  // Its handle and spout show in its belly: it stays reflected, and the parts split by curvature.
  scene.objects[teapot].mirror = MirrorInfo{MirrorCurvature::Mixed, true, std::nullopt, std::nullopt, std::nullopt};

  // Translating only in y keeps uv = world (x, z): checker cells are world-aligned unit squares.
  addObject(scene, "floor", addMesh(scene, primitives::grid("floor", 40.0f, 40.0f, 20, 20)),
            addMaterial(scene, checker("floor-checker", 0xE6E6E6, 0x191919, 1.0f, true)));
  addObject(scene, "red-box", addMesh(scene, primitives::box("red-box", {1.6f, 1.6f, 1.6f})),
            addMaterial(scene, matte("red", 0xD03020)), placed({1.5f, 0.8f, -4.2f}, 25.0f));
  addObject(scene, "green-ball", addMesh(scene, primitives::uvSphere("green-ball", 1.0f, 48, 24)),
            addMaterial(scene, matte("green", 0x30B040)), placed({-4.0f, 1.0f, 2.2f}));
  addObject(scene, "yellow-pillar", addMesh(scene, primitives::box("yellow-pillar", {0.8f, 4.5f, 0.8f})),
            addMaterial(scene, matte("yellow", 0xE0C020)), placed({-4.5f, 2.25f, -2.5f}, 35.0f));
  addObject(scene, "blue-ring", addMesh(scene, primitives::torus("blue-ring", 0.9f, 0.3f, 48, 16)),
            addMaterial(scene, matte("blue", 0x3050D0)), placed({4.6f, 0.3f, 1.0f}));

  scene.animations.push_back({std::nullopt, Orbit{glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}, 15.0}});
  return scene;
}

}  // namespace specula::scene::builtin
