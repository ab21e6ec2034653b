// Issue 17's case for the frame planner: thirty chrome beads, one or two pixels wide at 640x480,
// scattered over the teapot table (~20k vertices) whose big mirror ball is porcelain here. Searched,
// every bead would search every vertex of the table; the planner ray-casts mirrors this small.
#include <cmath>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

Scene beadsScene() {
  Scene scene = teapotTableScene();
  const std::uint32_t porcelain = addMaterial(scene, matte("ball-porcelain", 0xE8E4DA));
  for (SceneObject& object : scene.objects) {
    if (!object.mirror) continue;
    object.mirror.reset();
    object.material = porcelain;
    object.reflected = true;
  }

  constexpr int kBeads = 30;
  constexpr float kBeadRadius = 0.003f;
  const std::uint32_t beadMesh = addMesh(scene, primitives::uvSphere("bead", kBeadRadius, 16, 8));
  const std::uint32_t chrome = addMaterial(scene, perfectMirror("bead-chrome"));
  // A sunflower spiral over the table's front half, clear of the teapot and the candlestick.
  constexpr float kGoldenAngle = 2.39996323f;
  for (int i = 0; i < kBeads; ++i) {
    const float radius = 0.55f * std::sqrt((static_cast<float>(i) + 0.5f) / kBeads);
    const float angle = kGoldenAngle * static_cast<float>(i);
    const glm::vec3 at{0.1f + radius * std::cos(angle), kBeadRadius, 0.45f + 0.6f * radius * std::sin(angle)};
    const std::uint32_t bead =
        addSphereMirror(scene, "bead-" + std::to_string(i + 1), beadMesh, chrome, kBeadRadius, placed(at));
    scene.objects[bead].reflected = false;  // a bead in another bead would be far below a pixel
  }
  return scene;
}

}  // namespace specula::scene::builtin
