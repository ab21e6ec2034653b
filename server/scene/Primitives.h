#pragma once
// Procedural meshes for built-in scenes and for `"primitive"` meshes in scene files.
// All are in object space, counter-clockwise front faces, unit normals pointing outwards.
#include <glm/glm.hpp>
#include <span>
#include <string>

#include "scene/Mesh.h"

namespace specula::scene::primitives {

// Plane in XZ centred at the origin, normal +y, cellsX × cellsZ quads (two triangles each).
// uv = object-space (x, z) in metres, so a checker with cellsPerUnit 1 has unit cells.
Mesh grid(std::string name, float sizeX, float sizeZ, int cellsX, int cellsZ);

// Sphere centred at the origin; uv = (longitude / 2π, latitude / π). slices ≥ 3, stacks ≥ 2.
Mesh uvSphere(std::string name, float radius, int slices, int stacks);

// Axis-aligned box centred at the origin with flat-shaded faces (24 vertices); uv per face in [0, 1].
Mesh box(std::string name, const glm::vec3& size);

// Cylinder about +y from y = 0 to y = height; caps optional. slices ≥ 3.
Mesh cylinder(std::string name, float radius, float height, int slices, bool capped);

// Torus about the y axis in the XZ plane. Both segment counts ≥ 3.
Mesh torus(std::string name, float majorRadius, float minorRadius, int majorSegments, int minorSegments);

// Surface of revolution about +y of a polyline profile of (radius ≥ 0, y) points, swept in `slices`
// steps. Normals come from the profile's tangent, turned so that a profile walked bottom to top at
// positive radius faces outwards. uv = (slice fraction, profile arc-length fraction).
Mesh lathe(std::string name, std::span<const glm::vec2> profile, int slices);

// Appends `part` transformed by `transform` (normals by its inverse transpose) to `into`.
void append(Mesh& into, const Mesh& part, const glm::mat4& transform);

}  // namespace specula::scene::primitives
