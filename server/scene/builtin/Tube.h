#pragma once
// Open tubes swept along a polyline: handles, spouts, antennae, grass — shapes lathe() cannot make.
#include <glm/glm.hpp>
#include <span>
#include <string>

#include "scene/Mesh.h"

namespace specula::scene::builtin {

// A circle of radii[k] swept through path[k] (at least two points, one radius each) with `sides`
// segments; ends are left open. Counter-clockwise front faces, unit normals pointing away from the path.
Mesh tube(std::string name, std::span<const glm::vec3> path, std::span<const float> radii, int sides);

// A handle: a tube of `tubeRadius` along the circular arc about `centre` in the XY plane, from
// `fromDegrees` to `toDegrees` counter-clockwise about +z (a torus segment).
Mesh arcHandle(std::string name, const glm::vec2& centre, float arcRadius, float fromDegrees, float toDegrees,
               float tubeRadius);

}  // namespace specula::scene::builtin
