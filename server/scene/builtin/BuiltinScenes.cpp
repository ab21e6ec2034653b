#include "scene/builtin/BuiltinScenes.h"

#include <algorithm>
#include <array>

#include "scene/builtin/BuiltinSceneGenerators.h"

namespace specula::scene {

namespace {

struct Entry {
  std::string_view name;
  std::string_view summary;
  Scene (*make)();
};

constexpr std::array kEntries{
    Entry{"checker-sphere", "mirror sphere of radius 1 over an unlit 16 m checker floor; the camera orbits",
          builtin::checkerSphereScene},
    Entry{"mesh-sphere",
          "checker-sphere with its mirror as what real mirrors are, a 128x64 mesh (the sphere only measures it)",
          builtin::meshSphereScene},
    Entry{"cylinder",
          "mirror cylinder (a declared extrusion of a circle) among a box, a ball and a pillar on the checker floor",
          builtin::cylinderScene},
    Entry{"kitchen", "metal bowl (mixed curvature) on a kitchen table with fruit, cup and bottle (~15k vertices)",
          builtin::kitchenScene},
    Entry{"ufo", "spinning mirror saucer descending over a city square with driving trucks (~80k vertices)",
          builtin::ufoScene},
    Entry{"ants", "four walking ants whose eight eyes are small mirror spheres, among leaves and cans (~30k vertices)",
          builtin::antsScene},
    Entry{"quad", "one two-triangle checker quad spinning under a mirror sphere: the coarse tessellation case",
          builtin::quadScene},
    Entry{"teapot-table", "mirror ball beside a coarse tablecloth and candlestick and a fine procedural teapot",
          builtin::teapotTableScene},
    Entry{"beads", "thirty chrome beads a pixel or two wide on the teapot table (~20k vertices): many tiny mirrors",
          builtin::beadsScene},
    Entry{"utah-teapot",
          "chrome Utah teapot (32 Bezier patches, a parametric mirror) among coloured objects on a checker floor",
          builtin::utahTeapotScene},
    Entry{
        "flag",
        "a flag rippling on a pole beside a chrome ball, reshaped every frame by two morph targets: deforming geometry",
        builtin::flagScene},
};

constexpr auto kNames = [] {
  std::array<std::string_view, kEntries.size()> names{};
  std::ranges::transform(kEntries, names.begin(), &Entry::name);
  return names;
}();

const Entry* find(std::string_view name) {
  const auto it = std::ranges::find(kEntries, name, &Entry::name);
  return it == kEntries.end() ? nullptr : &*it;
}

}  // namespace

std::span<const std::string_view> builtinSceneNames() { return kNames; }

std::optional<Scene> makeBuiltinScene(std::string_view name) {
  const Entry* entry = find(name);
  if (!entry) return std::nullopt;
  Scene scene = entry->make();
  scene.name = std::string(entry->name);
  return scene;
}

std::string_view builtinSceneSummary(std::string_view name) {
  const Entry* entry = find(name);
  return entry ? entry->summary : std::string_view{};
}

}  // namespace specula::scene
