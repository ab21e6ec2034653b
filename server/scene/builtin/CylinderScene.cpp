// A mirror cylinder (Ofek & Rappoport 1998, fig. 12): an open 128-slice tube declared as the
// extrusion of a circle, so its reflection points can be solved exactly in 2-D or searched on the mesh.
#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

Scene cylinderScene() {
  constexpr float kRadius = 0.6f, kHeight = 1.8f;
  Scene scene;
  scene.ambient = glm::vec3(0.08f);
  scene.background = srgbHex(0x3A4A66);  // a dusk sky, so the mirror's upper part shows where it is
  scene.camera = {{3.8f, 1.5f, 3.4f}, {0.0f, 0.8f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
  scene.lights.push_back(sunLight({0.4f, 1.0f, 0.6f}, 1.0f));

  // The tube is the mirror; a closed twin with caps bounds it for the search, and a lid (not a
  // mirror) keeps the eye out of its inside, which is concave.
  const std::uint32_t tube = addObject(
      scene, "mirror-cylinder", addMesh(scene, primitives::cylinder("mirror-cylinder", kRadius, kHeight, 128, false)),
      addMaterial(scene, perfectMirror("mirror")));
  MirrorInfo& info = scene.objects[tube].mirror.emplace();
  info.curvature = MirrorCurvature::Convex;
  info.closed = false;
  info.closedTwinMesh = addMesh(scene, primitives::cylinder("mirror-cylinder-closed", kRadius, kHeight, 128, true));
  info.extrusion = math::Extrusion::along(glm::dvec3(0.0), {0.0, 1.0, 0.0}, glm::dvec2(kRadius));
  scene.objects[tube].reflected = false;  // its outside is convex: it never shows itself
  addObject(scene, "lid", addMesh(scene, primitives::cylinder("lid", kRadius, 0.03f, 128, true)),
            addMaterial(scene, matte("lid-grey", 0x707070)), placed({0.0f, kHeight, 0.0f}));

  // Translating only in y keeps uv = world (x, z), so checker cells are world-aligned unit squares.
  addObject(scene, "floor", addMesh(scene, primitives::grid("floor", 16.0f, 16.0f, 16, 16)),
            addMaterial(scene, checker("floor-checker", 0xE6E6E6, 0x191919, 1.0f, true)));
  addObject(scene, "red-box", addMesh(scene, primitives::box("red-box", {0.5f, 0.6f, 0.5f})),
            addMaterial(scene, matte("red", 0xD03020)), placed({1.7f, 0.3f, 0.3f}, 20.0f));
  addObject(scene, "green-ball", addMesh(scene, primitives::uvSphere("green-ball", 0.35f, 32, 16)),
            addMaterial(scene, matte("green", 0x30B040)), placed({-0.6f, 0.35f, 1.7f}));
  addObject(scene, "yellow-pillar", addMesh(scene, primitives::box("yellow-pillar", {0.3f, 1.6f, 0.3f})),
            addMaterial(scene, matte("yellow", 0xE0C020)), placed({-1.9f, 0.8f, 0.5f}, 35.0f));

  scene.animations.push_back({std::nullopt, Orbit{glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}, 20.0}});
  return scene;
}

}  // namespace specula::scene::builtin
