// Deforming geometry (issue #40): a flag waving on a pole beside a chrome ball, facing it, its cloth reshaped every
// frame by two morph targets whose weights turn like a clock hand, so the ripple travels along it. The
// virtual objects need nothing precomputed for it; a ray caster must refit its hierarchy every frame.
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

namespace {

constexpr float kWidth = 3.0f, kHeight = 1.8f;  // the cloth, metres
constexpr float kAmplitude = 0.3f;              // of the ripple at the free edge; zero at the pole
constexpr float kWaves = 1.25f;                 // ripples across the cloth
constexpr double kPeriod = 1.6;                 // seconds a ripple takes to pass
constexpr int kKeysPerPeriod = 48;

// The cloth, a grid facing +z with its left edge at x = 0 on the pole, and two targets: A(x)·sin kx and
// A(x)·cos kx along z, A growing linearly from the pole. Weighted (cos ωt, −sin ωt) they make the ripple
// A(x)·sin(kx − ωt); their normal displacements are the exact surface normal's, (−∂z/∂x, 0, 1) being linear
// in the weights.
Mesh cloth() {
  Mesh mesh = primitives::grid("flag", kWidth, kHeight, 48, 24);
  // The grid lies in xz about the origin, facing +y: stand it up facing +z, its left edge at x = 0.
  const glm::mat4 stand = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(kWidth / 2, 0.0f, 0.0f)),
                                      glm::half_pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f));
  Mesh flag;
  flag.name = "flag";
  primitives::append(flag, mesh, stand);
  const float k = 2.0f * glm::pi<float>() * kWaves / kWidth;
  MorphTarget sine, cosine;
  for (const Vertex& v : flag.vertices) {
    const float x = v.position.x, a = kAmplitude * x / kWidth, slope = kAmplitude / kWidth;
    sine.positions.emplace_back(0.0f, 0.0f, a * std::sin(k * x));
    cosine.positions.emplace_back(0.0f, 0.0f, a * std::cos(k * x));
    sine.normals.emplace_back(-(slope * std::sin(k * x) + a * k * std::cos(k * x)), 0.0f, 0.0f);
    cosine.normals.emplace_back(-(slope * std::cos(k * x) - a * k * std::sin(k * x)), 0.0f, 0.0f);
  }
  flag.morphTargets = {std::move(sine), std::move(cosine)};
  return flag;
}

// One node carrying the flag, and the clip turning its weights once a period.
NodeRig flagRig(std::uint32_t object) {
  NodeRig rig;
  rig.nodes.emplace_back();
  NodeChannel weights;
  weights.property = NodeProperty::Weights;
  for (int key = 0; key <= kKeysPerPeriod; ++key) {
    const double t = kPeriod * key / kKeysPerPeriod, angle = 2.0 * glm::pi<double>() * key / kKeysPerPeriod;
    weights.times.push_back(t);
    weights.values.emplace_back(std::cos(angle), -std::sin(angle), 0.0, 0.0);
  }
  const double duration = weights.times.back();
  rig.clips.push_back({"wave", {std::move(weights)}, duration});
  rig.objects.push_back({object, 0});
  rig.morphed.push_back({object, 0, {1.0f, 0.0f}});
  return rig;
}

}  // namespace

Scene flagScene() {
  Scene scene;
  scene.environment.kind = EnvironmentKind::Sky;
  scene.camera = {{0.6f, 2.2f, 5.5f}, {0.2f, 1.3f, 0.0f}, {0.0f, 1.0f, 0.0f}, 45.0f};
  scene.lights.push_back(sunLight({0.4f, 1.0f, 0.8f}, 1.0f));

  addSphereMirror(scene, "ball", addMesh(scene, primitives::uvSphere("ball", 0.8f, 96, 48)),
                  addMaterial(scene, perfectMirror("chrome")), 0.8f, placed({0.3f, 0.9f, 0.2f}));
  scene.objects.back().mirror->analytic->exactSurface = false;  // a mesh: the general case, searched
  addObject(scene, "floor", addMesh(scene, primitives::grid("floor", 12.0f, 12.0f, 12, 12)),
            addMaterial(scene, checker("floor-checker", 0xD8D8D8, 0x3A3A3A, 1.0f, false)));
  addObject(scene, "pole", addMesh(scene, primitives::cylinder("pole", 0.04f, 3.2f, 16, true)),
            addMaterial(scene, matte("pole", 0x8A6A4A)), placed({-1.9f, 0.0f, 1.2f}));
  const std::uint32_t flag =
      addObject(scene, "flag", addMesh(scene, cloth()), addMaterial(scene, matte("flag", 0xC8202A)),
                placed({-1.9f, 2.2f, 1.2f}, 90.0f));  // reaching back, facing the ball
  scene.rig = flagRig(flag);
  return scene;
}

}  // namespace specula::scene::builtin
