// The reference scene: simple enough that exact reflections can be computed analytically.
#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

namespace {

Scene checkerSphere(bool exactSurface) {
  Scene scene;
  scene.ambient = glm::vec3(0.0f);
  scene.environment.kind = EnvironmentKind::Sky;  // the chrome sphere reflects a sky, not a black disc
  scene.camera = {{1.0f, 3.0f, 3.5f}, {0.0f, -0.3f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};

  const std::uint32_t sphere =
      addSphereMirror(scene, "mirror-sphere", addMesh(scene, primitives::uvSphere("mirror-sphere", 1.0f, 128, 64)),
                      addMaterial(scene, perfectMirror("mirror")), 1.0f, {});
  // The only mirror is a convex sphere, which can never show itself.
  scene.objects[sphere].reflected = false;
  scene.objects[sphere].mirror->analytic->exactSurface = exactSurface;

  // Translating only in y keeps uv = world (x, z), so checker cells are world-aligned unit squares.
  addObject(scene, "floor", addMesh(scene, primitives::grid("floor", 16.0f, 16.0f, 16, 16)),
            addMaterial(scene, checker("floor-checker", 0xE6E6E6, 0x191919, 1.0f, true)), placed({0.0f, -1.0f, 0.0f}));

  scene.animations.push_back({std::nullopt, Orbit{glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}, 20.0}});
  return scene;
}

}  // namespace

Scene checkerSphereScene() { return checkerSphere(true); }

// The same sphere as the general case, a mesh: the quadric only measures its reflection points.
Scene meshSphereScene() { return checkerSphere(false); }

}  // namespace specula::scene::builtin
