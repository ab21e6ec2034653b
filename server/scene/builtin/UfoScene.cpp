// After Estalella et al. 2006 (their UFO scene: one big reflector over a city, trucks driving
// around the central square, ~80k vertices). A 5 × 5 grid of blocks; the middle one is the square.
#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>
#include <vector>

#include "scene/Primitives.h"
#include "scene/builtin/BuiltinSceneGenerators.h"
#include "scene/builtin/SceneAssembly.h"
#include "scene/builtin/SceneRandom.h"

namespace specula::scene::builtin {

namespace {

constexpr int kBlocks = 5;
constexpr float kBlockSize = 14.0f, kStreetWidth = 8.0f, kPitch = kBlockSize + kStreetWidth;
constexpr float kCityHalf = kBlocks * kPitch / 2.0f + kStreetWidth / 2.0f;  // to the outer edge of the border streets
constexpr float kSaucerRadius = 9.0f;

// Centre line of street k (0 … kBlocks), running between blocks k − 1 and k.
constexpr float streetLine(int k) { return (static_cast<float>(k) - kBlocks / 2.0f) * kPitch; }
// Centre of block i (0 … kBlocks − 1) along one axis.
constexpr float blockCentre(int i) { return (static_cast<float>(i) - (kBlocks - 1) / 2.0f) * kPitch; }

// A lens: an elliptical underside meeting a paraboloid top at a sharp rim. Both are convex, and the
// rim turns the same way, so the whole saucer is a convex mirror.
Mesh saucerMesh() {
  constexpr float kUnderside = 1.4f, kTop = 3.4f;
  std::vector<glm::vec2> profile = ellipseArc({0.0f, 0.0f}, {kSaucerRadius, kUnderside}, -90.0f, 0.0f, 36);
  constexpr int kTopPoints = 44;
  for (int k = 1; k <= kTopPoints; ++k) {
    const float u = 1.0f - static_cast<float>(k) / kTopPoints;
    profile.push_back({kSaucerRadius * u, kTop * (1.0f - u * u)});
  }
  return primitives::lathe("saucer", profile, 192);
}

// Running lights under the rim and portholes round the top, spinning with the saucer.
Mesh saucerLightsMesh() {
  Mesh lights{"saucer-lights", {}, {}};
  primitives::append(lights, primitives::torus("light-ring", 6.5f, 0.18f, 128, 8),
                     placed({0.0f, -0.92f, 0.0f}).matrix());
  const Mesh porthole = primitives::uvSphere("porthole", 0.3f, 12, 6);
  constexpr int kPortholes = 16;
  for (int k = 0; k < kPortholes; ++k) {
    const float a = glm::two_pi<float>() * static_cast<float>(k) / kPortholes;
    constexpr float r = 6.0f;
    const float y = 3.4f * (1.0f - (r / kSaucerRadius) * (r / kSaucerRadius));
    primitives::append(lights, porthole, placed({r * std::cos(a), y, r * std::sin(a)}).matrix());
  }
  return lights;
}

// Box truck facing +x, standing on y = 0: cab and cargo box in one mesh, wheels in another.
Mesh truckBodyMesh() {
  Mesh body{"truck-body", {}, {}};
  primitives::append(body, primitives::box("cab", {1.8f, 2.2f, 2.3f}), placed({2.4f, 1.6f, 0.0f}).matrix());
  primitives::append(body, primitives::box("cargo", {4.6f, 2.6f, 2.4f}), placed({-0.9f, 1.8f, 0.0f}).matrix());
  return body;
}

Mesh truckWheelsMesh() {
  Mesh wheels{"truck-wheels", {}, {}};
  const Mesh wheel = primitives::cylinder("wheel", 0.5f, 0.4f, 12, true);
  // The cylinder's axis (+y) turned onto ±z, the wheel centred on its axle.
  const glm::quat axle = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));
  for (const float x : {2.4f, -0.2f, -2.2f})
    for (const float side : {1.0f, -1.0f})
      primitives::append(wheels, wheel,
                         math::Transform{{x, 0.5f, side * 1.05f - 0.2f}, axle, glm::vec3(1.0f)}.matrix());
  return wheels;
}

// Drives round the rectangle with corners `corners` (street coordinates, in order) on the right-hand
// lane at `speed` m/s, easing through each corner; the last key repeats the first, so it loops seamlessly.
TransformPath drive(const std::array<glm::vec2, 4>& corners, float speed) {
  constexpr float kLane = 2.0f, kTurn = 3.0f;
  const auto direction = [&](std::size_t from, std::size_t to) {
    return glm::normalize(corners[to % 4] - corners[from % 4]);
  };
  const auto right = [](const glm::vec2& d) { return glm::vec2(-d.y, d.x); };  // (x, z) of d × up
  const auto headingDegrees = [](const glm::vec2& d) { return glm::degrees(std::atan2(-d.y, d.x)); };
  struct Pose {
    glm::vec2 at;
    glm::vec2 heading;
  };
  std::vector<Pose> poses;
  for (std::size_t i = 0; i <= 4; ++i) {
    const glm::vec2 in = direction(i + 3, i), out = direction(i, i + 1);
    const glm::vec2 corner = corners[i % 4] + kLane * (right(in) + right(out));
    if (i > 0) poses.push_back({corner - kTurn * in, in});
    poses.push_back({corner + kTurn * out, out});
  }
  TransformPath path;
  double time = 0.0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    if (k > 0) time += glm::distance(poses[k - 1].at, poses[k].at) / speed;
    path.keys.push_back({time, placed({poses[k].at.x, 0.0f, poses[k].at.y}, headingDegrees(poses[k].heading))});
  }
  return path;
}

}  // namespace

Scene ufoScene() {
  Scene scene;
  scene.ambient = glm::vec3(0.12f);
  scene.background = srgbHex(0x87A9C9);
  scene.lights.push_back(sunLight({-0.5f, 1.0f, 0.3f}, 1.0f));
  // At street level on the corner of the square, looking up at the underside the city reflects in.
  scene.camera = {{13.0f, 2.0f, 17.0f}, {0.0f, 12.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 60.0f};
  SceneRandom random(1998);

  // Asphalt everywhere; blocks are raised kerbs on it. Finely gridded: it fills most of the mirror.
  addObject(scene, "ground", addMesh(scene, primitives::grid("ground", 2 * kCityHalf, 2 * kCityHalf, 144, 144)),
            addMaterial(scene, matte("asphalt", 0x3C3F44)));
  addObject(scene, "square", addMesh(scene, primitives::grid("square", kBlockSize, kBlockSize, 28, 28)),
            addMaterial(scene, checker("paving", 0xC9C2B2, 0x9E9584, 1.0f, false)), placed({0.0f, 0.005f, 0.0f}));

  const Mesh unitBox = primitives::box("unit-box", glm::vec3(1.0f));
  constexpr std::array<std::uint32_t, 8> kFacades{0xC9B79C, 0xA3A3A3, 0x8A6F5A, 0xD9D4C7,
                                                  0x6F7F8F, 0xB07D62, 0x9DAF9F, 0x7B6E8A};
  std::array<Mesh, kFacades.size()> facades;
  for (std::size_t c = 0; c < facades.size(); ++c) facades[c].name = "buildings-" + std::to_string(c);
  Mesh kerbs{"kerbs", {}, {}}, roofs{"rooftops", {}, {}}, tanks{"water-tanks", {}, {}};
  Mesh trees{"tree-crowns", {}, {}}, trunks{"tree-trunks", {}, {}};
  const Mesh crown = primitives::uvSphere("crown", 1.0f, 12, 8);
  const Mesh trunk = primitives::cylinder("trunk", 0.2f, 2.5f, 8, false);
  const Mesh tank = primitives::cylinder("tank", 0.9f, 1.8f, 12, true);
  for (int bx = 0; bx < kBlocks; ++bx)
    for (int bz = 0; bz < kBlocks; ++bz) {
      const glm::vec3 centre{blockCentre(bx), 0.0f, blockCentre(bz)};
      if (bx == kBlocks / 2 && bz == kBlocks / 2) {
        // The square: trees round its edge, open in the middle where the saucer comes down.
        constexpr int kTrees = 36;
        for (int k = 0; k < kTrees; ++k) {
          const float a = glm::two_pi<float>() * static_cast<float>(k) / kTrees;
          const glm::vec3 at = centre + 5.8f * glm::vec3(std::cos(a), 0.0f, std::sin(a));
          primitives::append(trunks, trunk, placed(at).matrix());
          primitives::append(trees, crown, placed(at + glm::vec3(0.0f, 3.2f, 0.0f), 0.0f, {1.1f, 1.3f, 1.1f}).matrix());
        }
        continue;
      }
      primitives::append(
          kerbs, unitBox,
          placed(centre + glm::vec3(0.0f, 0.075f, 0.0f), 0.0f, {kBlockSize, 0.15f, kBlockSize}).matrix());
      // Three by three lots, each with a building of random footprint, height and facade.
      for (int lx = -1; lx <= 1; ++lx)
        for (int lz = -1; lz <= 1; ++lz) {
          const glm::vec3 lot = centre + glm::vec3(static_cast<float>(lx), 0.0f, static_cast<float>(lz)) * 4.4f;
          glm::vec3 size{random.uniform(3.0f, 4.2f), random.uniform(6.0f, 34.0f), random.uniform(3.0f, 4.2f)};
          Mesh& facade = facades[random.index(kFacades.size())];
          float base = 0.15f;
          primitives::append(facade, unitBox,
                             placed(lot + glm::vec3(0.0f, base + size.y / 2, 0.0f), 0.0f, size).matrix());
          base += size.y;
          if (size.y > 20.0f) {  // towers step back once
            size *= glm::vec3(0.7f, random.uniform(0.2f, 0.4f), 0.7f);
            primitives::append(facade, unitBox,
                               placed(lot + glm::vec3(0.0f, base + size.y / 2, 0.0f), 0.0f, size).matrix());
            base += size.y;
          }
          const glm::vec3 roof{size.x * 0.4f, random.uniform(0.8f, 2.5f), size.z * 0.4f};
          primitives::append(roofs, unitBox,
                             placed(lot + glm::vec3(0.0f, base + roof.y / 2, 0.0f), 0.0f, roof).matrix());
          if (random.uniform(0.0f, 1.0f) < 0.35f)
            primitives::append(tanks, tank, placed(lot + glm::vec3(size.x * 0.25f, base, -size.z * 0.25f)).matrix());
        }
    }
  for (std::size_t c = 0; c < facades.size(); ++c) {
    std::string name = facades[c].name;  // copied first: the mesh is moved from in the same call
    addObject(scene, std::move(name), addMesh(scene, std::move(facades[c])),
              addMaterial(scene, matte("facade-" + std::to_string(c), kFacades[c])));
  }
  addObject(scene, "kerbs", addMesh(scene, std::move(kerbs)), addMaterial(scene, matte("pavement", 0xA9A49A)));
  addObject(scene, "rooftops", addMesh(scene, std::move(roofs)), addMaterial(scene, matte("roof", 0x55585C)));
  addObject(scene, "water-tanks", addMesh(scene, std::move(tanks)), addMaterial(scene, matte("tank-wood", 0x7A5A3A)));
  addObject(scene, "tree-crowns", addMesh(scene, std::move(trees)), addMaterial(scene, matte("foliage", 0x3F7F3A)));
  addObject(scene, "tree-trunks", addMesh(scene, std::move(trunks)), addMaterial(scene, matte("bark", 0x5A4030)));

  // Dashed centre lines along every street, left out at crossings; lamp posts at every block corner.
  Mesh dashes{"lane-markings", {}, {}}, posts{"lamp-posts", {}, {}}, lamps{"lamp-lights", {}, {}};
  const Mesh post = primitives::cylinder("post", 0.12f, 6.0f, 8, false);
  const Mesh lamp = primitives::uvSphere("lamp", 0.35f, 8, 4);
  for (int k = 0; k <= kBlocks; ++k)
    for (int i = 0; i < kBlocks; ++i)
      for (int d = -2; d <= 2; ++d) {
        const float along = blockCentre(i) + static_cast<float>(d) * 3.0f, line = streetLine(k);
        primitives::append(dashes, unitBox, placed({along, 0.01f, line}, 0.0f, {1.6f, 0.02f, 0.15f}).matrix());
        primitives::append(dashes, unitBox, placed({line, 0.01f, along}, 0.0f, {0.15f, 0.02f, 1.6f}).matrix());
      }
  for (int bx = 0; bx < kBlocks; ++bx)
    for (int bz = 0; bz < kBlocks; ++bz)
      for (const float sx : {-1.0f, 1.0f})
        for (const float sz : {-1.0f, 1.0f}) {
          const float kerb = bx == kBlocks / 2 && bz == kBlocks / 2 ? 0.0f : 0.15f;  // the square has no kerb
          const glm::vec3 at{blockCentre(bx) + sx * (kBlockSize / 2 - 0.5f), kerb,
                             blockCentre(bz) + sz * (kBlockSize / 2 - 0.5f)};
          primitives::append(posts, post, placed(at).matrix());
          primitives::append(lamps, lamp, placed(at + glm::vec3(0.0f, 6.2f, 0.0f)).matrix());
        }
  addObject(scene, "lane-markings", addMesh(scene, std::move(dashes)),
            addMaterial(scene, matte("road-paint", 0xF2F2F2)));
  addObject(scene, "lamp-posts", addMesh(scene, std::move(posts)), addMaterial(scene, matte("lamp-post", 0x2F3136)));
  addObject(scene, "lamp-lights", addMesh(scene, std::move(lamps)),
            addMaterial(scene, emissive("lamp-glow", 0xFFE9A8)));

  // Trucks loop round rectangles of streets, most of them passing the square under the saucer.
  const std::uint32_t truckBody = addMesh(scene, truckBodyMesh());
  const std::uint32_t truckWheels = addMesh(scene, truckWheelsMesh());
  const std::uint32_t tyres = addMaterial(scene, matte("tyre", 0x1C1C1C));
  constexpr std::array<std::uint32_t, 5> kPaints{0xD7263D, 0xF4A259, 0x1B998B, 0x2E86AB, 0xE8E1D9};
  std::array<std::uint32_t, kPaints.size()> paints{};
  for (std::size_t c = 0; c < paints.size(); ++c)
    paints[c] = addMaterial(scene, matte("truck-paint-" + std::to_string(c), kPaints[c]));
  // Rectangles as (first street x, first street z, last street x, last street z), driven +x first
  // (clockwise seen from above) or, with `reverse`, the other way round.
  struct Route {
    int x0, z0, x1, z1;
    bool reverse;
    float speed;
  };
  constexpr std::array<Route, 10> kRoutes{Route{2, 2, 3, 3, false, 7.0f},  Route{2, 2, 3, 3, true, 6.0f},
                                          Route{1, 2, 4, 3, false, 9.0f},  Route{2, 1, 3, 4, true, 8.0f},
                                          Route{0, 0, 3, 3, false, 10.0f}, Route{2, 2, 5, 5, true, 9.5f},
                                          Route{1, 1, 4, 4, false, 8.5f},  Route{0, 2, 5, 3, true, 11.0f},
                                          Route{2, 0, 3, 5, false, 10.5f}, Route{0, 0, 5, 5, true, 12.0f}};
  for (std::size_t t = 0; t < kRoutes.size(); ++t) {
    const Route& r = kRoutes[t];
    std::array<glm::vec2, 4> corners{
        glm::vec2(streetLine(r.x0), streetLine(r.z0)), glm::vec2(streetLine(r.x1), streetLine(r.z0)),
        glm::vec2(streetLine(r.x1), streetLine(r.z1)), glm::vec2(streetLine(r.x0), streetLine(r.z1))};
    if (r.reverse) std::swap(corners[1], corners[3]);
    const TransformPath path = drive(corners, r.speed);
    const std::string name = "truck-" + std::to_string(t + 1);
    const math::Transform start = path.keys.front().transform;
    scene.animations.push_back({addObject(scene, name, truckBody, paints[t % paints.size()], start), path});
    scene.animations.push_back({addObject(scene, name + "-wheels", truckWheels, tyres, start), path});
  }

  // The saucer comes down over the square, hovers, and climbs away again, spinning all the while.
  const std::uint32_t saucer = addObject(scene, "saucer", addMesh(scene, saucerMesh()),
                                         addMaterial(scene, mirror("saucer-hull", 0xB8C0C8, 0.9f)));
  scene.objects[saucer].mirror = MirrorInfo{MirrorCurvature::Convex, true, std::nullopt, std::nullopt, std::nullopt};
  scene.objects[saucer].reflected = false;  // the only mirror, and convex: it never shows itself
  const std::uint32_t saucerLights = addObject(scene, "saucer-lights", addMesh(scene, saucerLightsMesh()),
                                               addMaterial(scene, emissive("saucer-glow", 0x7CF5FF)));
  TransformPath flight{{{0.0, placed({0.0f, 34.0f, 0.0f})},
                        {14.0, placed({0.0f, 11.0f, 0.0f})},
                        {20.0, placed({0.0f, 12.0f, 0.0f})},
                        {34.0, placed({0.0f, 34.0f, 0.0f})}},
                       true};
  for (const std::uint32_t part : {saucer, saucerLights}) {
    scene.objects[part].transform = flight.keys.front().transform;
    scene.animations.push_back({part, flight});
    scene.animations.push_back({part, Spin{{0.0f, 1.0f, 0.0f}, 12.0}});  // after the path, which resets the rotation
  }
  return scene;
}

}  // namespace specula::scene::builtin
