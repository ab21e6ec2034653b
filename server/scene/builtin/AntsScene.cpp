// After Estalella et al. 2006 (their ant scene: eight reflectors, the eyes of four ants, ~30k
// vertices, with drink cans whose long thin triangles need tessellation to curve in the eyes).
// Everything is 30 times life size, so an ant is 0.3 m long and the camera's near plane stays practical.
#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>
#include <vector>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"
#include "scene/builtin/SceneRandom.h"
#include "scene/builtin/Tube.h"

namespace specula::scene::builtin {

namespace {

constexpr float kEyeRadius = 0.012f;
// Eye centres in ant space (forward +x, left −z, standing on y = 0), half sunk into the head.
constexpr std::array<glm::vec3, 2> kEyes{glm::vec3(0.125f, 0.11f, 0.04f), glm::vec3(0.125f, 0.11f, -0.04f)};

// Head, thorax, waist and abdomen from scaled spheres; six legs and two antennae from thin tubes.
Mesh antMesh() {
  Mesh ant{"ant", {}, {}};
  const Mesh sphere = primitives::uvSphere("segment", 1.0f, 24, 12);
  primitives::append(ant, sphere, placed({-0.1f, 0.09f, 0.0f}, 0.0f, {0.09f, 0.065f, 0.07f}).matrix());     // abdomen
  primitives::append(ant, sphere, placed({-0.02f, 0.085f, 0.0f}, 0.0f, glm::vec3(0.022f)).matrix());        // waist
  primitives::append(ant, sphere, placed({0.03f, 0.095f, 0.0f}, 0.0f, {0.055f, 0.035f, 0.035f}).matrix());  // thorax
  primitives::append(ant, sphere, placed({0.11f, 0.1f, 0.0f}, 0.0f, {0.045f, 0.04f, 0.042f}).matrix());     // head
  const std::array<float, 3> legRadii{0.006f, 0.005f, 0.003f};
  const std::array<float, 3> antennaRadii{0.004f, 0.0035f, 0.002f};
  for (const float side : {1.0f, -1.0f}) {
    for (const float hipX : {0.0f, 0.03f, 0.06f}) {
      const float reach = (hipX - 0.03f) * 3.0f;  // front legs reach forwards, hind legs back
      const std::array<glm::vec3, 3> leg{glm::vec3(hipX, 0.085f, side * 0.03f),
                                         glm::vec3(hipX + reach * 0.5f, 0.13f, side * 0.12f),
                                         glm::vec3(hipX + reach, 0.0f, side * 0.19f)};
      primitives::append(ant, tube("leg", leg, legRadii, 8), glm::mat4(1.0f));
    }
    const std::array<glm::vec3, 3> antenna{glm::vec3(0.13f, 0.125f, side * 0.015f),
                                           glm::vec3(0.16f, 0.17f, side * 0.04f),
                                           glm::vec3(0.22f, 0.15f, side * 0.07f)};
    primitives::append(ant, tube("antenna", antenna, antennaRadii, 6), glm::mat4(1.0f));
  }
  return ant;
}

// A drink can: one band of 64 tall, thin quads between bevelled ends.
Mesh canMesh() {
  const std::vector<glm::vec2> profile{{0.0f, 0.04f},  {0.68f, 0.0f}, {0.75f, 0.12f},
                                       {0.75f, 3.55f}, {0.66f, 3.7f}, {0.0f, 3.66f}};
  return primitives::lathe("can", profile, 64);
}

// A walking path: a circle about `centre`, the ant starting at `startDegrees` and facing along its way.
struct Walk {
  glm::vec3 centre;
  float radius;
  float startDegrees;
  double degreesPerSecond;
};

// Props stay outside these discs (x, z, radius): the circles the ants walk and the cans.
constexpr std::array<glm::vec3, 6> kKeepOut{glm::vec3(0.0f, 0.0f, 1.7f),  glm::vec3(-1.5f, 1.7f, 0.85f),
                                            glm::vec3(1.6f, 1.3f, 0.9f),  glm::vec3(-2.0f, -2.2f, 1.0f),
                                            glm::vec3(3.3f, -1.9f, 1.2f), glm::vec3(3.3f, 0.0f, 1.2f)};

// A point on the ground at least `clearance` outside every keep-out disc.
glm::vec3 freeSpot(SceneRandom& random, float clearance) {
  for (;;) {
    const glm::vec3 p{random.uniform(-4.6f, 4.6f), 0.0f, random.uniform(-4.6f, 4.6f)};
    bool clear = true;
    for (const glm::vec3& disc : kKeepOut)
      clear = clear && glm::distance(glm::vec2(p.x, p.z), glm::vec2(disc.x, disc.y)) > disc.z + clearance;
    if (clear) return p;
  }
}

}  // namespace

Scene antsScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.15f);
  scene.background = srgbHex(0x9CC3E6);
  scene.lights.push_back(sunLight({0.3f, 1.0f, 0.4f}, 1.0f));
  scene.camera = {{2.2f, 0.8f, 2.2f}, {0.0f, 0.05f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
  SceneRandom random(2006);

  addObject(scene, "ground", addMesh(scene, primitives::grid("ground", 10.0f, 10.0f, 96, 96)),
            addMaterial(scene, checker("soil", 0x7A5C3E, 0x6B4F34, 1.0f, false)));
  const std::uint32_t can = addMesh(scene, canMesh());
  addObject(scene, "can-standing", can, addMaterial(scene, matte("can-red", 0xC8102E)),
            placed({-2.0f, 0.0f, -2.2f}, 30.0f));
  // Lying along z: the can's axis (+y) turned down onto −z, resting on its side.
  addObject(scene, "can-lying", can, addMaterial(scene, matte("can-green", 0x1E7B3C)),
            {{3.3f, 0.75f, 0.9f}, glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0)), glm::vec3(1.0f)});

  const std::uint32_t leaf = addMesh(scene, primitives::uvSphere("leaf", 1.0f, 24, 12));
  const std::array<std::uint32_t, 2> leafColours{addMaterial(scene, matte("leaf-green", 0x4E8B3A)),
                                                 addMaterial(scene, matte("leaf-dry", 0xA8843A))};
  for (int k = 0; k < 10; ++k) {
    const glm::vec3 at = freeSpot(random, 0.6f);
    addObject(scene, "leaf-" + std::to_string(k), leaf, leafColours[k % 2],
              placed(at + glm::vec3(0.0f, 0.01f, 0.0f), random.uniform(0.0f, 360.0f),
                     {random.uniform(0.45f, 0.6f), 0.02f, 0.22f}));
  }

  // Pebbles and grass are many small props: one merged mesh per material keeps the object count low.
  const Mesh pebble = primitives::uvSphere("pebble", 1.0f, 16, 8);
  Mesh pebbles{"pebbles", {}, {}};
  for (int k = 0; k < 24; ++k) {
    const float size = random.uniform(0.05f, 0.2f);
    const glm::vec3 at = freeSpot(random, size);
    primitives::append(pebbles, pebble,
                       placed(at, random.uniform(0.0f, 360.0f),
                              size * glm::vec3(1.0f, random.uniform(0.4f, 0.7f), random.uniform(0.7f, 1.0f)))
                           .matrix());
  }
  addObject(scene, "pebbles", addMesh(scene, std::move(pebbles)), addMaterial(scene, matte("stone", 0x8D8A84)));

  Mesh grass{"grass", {}, {}};
  const std::array<float, 6> bladeRadii{0.02f, 0.018f, 0.015f, 0.011f, 0.007f, 0.002f};
  for (int k = 0; k < 60; ++k) {
    const float height = random.uniform(0.4f, 1.0f), bend = random.uniform(0.15f, 1.0f);
    std::array<glm::vec3, 6> blade{};
    for (std::size_t i = 0; i < blade.size(); ++i) {
      const float t = static_cast<float>(i) / static_cast<float>(blade.size() - 1);
      blade[i] = {bend * t * t, height * t, 0.0f};
    }
    // Squeezed along its bend so each blade is a ribbon curling over its flat side, not a straw.
    primitives::append(grass, tube("blade", blade, bladeRadii, 5),
                       placed(freeSpot(random, 0.1f), random.uniform(0.0f, 360.0f), {0.3f, 1.0f, 1.0f}).matrix());
  }
  addObject(scene, "grass", addMesh(scene, std::move(grass)), addMaterial(scene, matte("grass", 0x5E9E3A)));

  // Four ants walking circles, two of them one inside the other in opposite directions.
  const std::uint32_t antBody = addMesh(scene, antMesh());
  const std::uint32_t chitin = addMaterial(scene, matte("chitin", 0x3B1F14));
  const std::uint32_t eyeMesh = addMesh(scene, primitives::uvSphere("eye", kEyeRadius, 24, 16));
  const std::uint32_t eyeMaterial = addMaterial(scene, mirror("ant-eye", 0x050505, 0.85f));
  const std::array<Walk, 4> walks{
      Walk{{0.0f, 0.0f, 0.0f}, 0.8f, 0.0f, 12.0}, Walk{{0.0f, 0.0f, 0.0f}, 1.3f, 140.0f, -9.0},
      Walk{{-1.5f, 0.0f, 1.7f}, 0.5f, 60.0f, 15.0}, Walk{{1.6f, 0.0f, 1.3f}, 0.55f, 250.0f, -13.0}};
  for (std::size_t a = 0; a < walks.size(); ++a) {
    const Walk& walk = walks[a];
    const float angle = glm::radians(walk.startDegrees);
    // Orbit turns positions counter-clockwise about +y for a positive rate; face along the motion.
    const float heading = walk.startDegrees + (walk.degreesPerSecond > 0.0 ? 90.0f : -90.0f);
    const math::Transform body =
        placed(walk.centre + walk.radius * glm::vec3(std::cos(angle), 0.0f, -std::sin(angle)), heading);
    const Orbit orbit{walk.centre, {0.0f, 1.0f, 0.0f}, walk.degreesPerSecond};
    const std::string name = "ant-" + std::to_string(a + 1);
    scene.animations.push_back({addObject(scene, name, antBody, chitin, body), orbit});
    for (std::size_t e = 0; e < kEyes.size(); ++e) {
      const math::Transform eye{body.translation + body.rotation * kEyes[e], body.rotation, glm::vec3(1.0f)};
      const std::uint32_t eyeObject =
          addSphereMirror(scene, name + (e == 0 ? "-eye-right" : "-eye-left"), eyeMesh, eyeMaterial, kEyeRadius, eye);
      scene.animations.push_back({eyeObject, orbit});
    }
  }
  return scene;
}

}  // namespace specula::scene::builtin
