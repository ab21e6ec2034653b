// Two large triangles whose straight edges curve in the mirror: only tessellation makes that right.
#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

Scene quadScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.0f);
  scene.background = srgbHex(0x101418);
  scene.camera = {{0.0f, 1.2f, 4.5f}, {0.0f, -0.4f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};

  const std::uint32_t sphere =
      addSphereMirror(scene, "mirror-sphere", addMesh(scene, primitives::uvSphere("mirror-sphere", 1.0f, 96, 48)),
                      addMaterial(scene, perfectMirror("mirror")), 1.0f, {});
  scene.objects[sphere].reflected = false;  // the only mirror, and convex: it never shows itself

  // A 3 m quad of 6 × 6 checker cells drawn with one cell of geometry: two triangles.
  const std::uint32_t quad = addObject(scene, "quad", addMesh(scene, primitives::grid("quad", 3.0f, 3.0f, 1, 1)),
                                       addMaterial(scene, checker("quad-checker", 0xF2F2F2, 0xC0392B, 2.0f, true)),
                                       placed({0.0f, -1.25f, 0.0f}, 10.0f));
  scene.animations.push_back({quad, Spin{{0.0f, 1.0f, 0.0f}, 15.0}});
  return scene;
}

}  // namespace specula::scene::builtin
