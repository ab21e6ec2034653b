#pragma once
// A scene file's parametric surfaces: Bézier patches as written, or a B-spline surface split into them.
#include <vector>

#include "math/BezierPatch.h"
#include "scene/JsonNode.h"

namespace specula::scene::file {

// [[16 × [x, y, z]], ...]: bicubic Bézier patches, each four rows of four control points (u along a row).
std::vector<math::BezierPatch> readBezierPatches(const JsonNode& node);

// {"degree": [du, dv], "count": [nu, nv], "knots_u": [...], "knots_v": [...], "points": [nu·nv × [x, y, z]]}:
// a tensor-product B-spline surface, rows of nu points along u, nv rows along v.
std::vector<math::BezierPatch> readBSpline(const JsonNode& node);

}  // namespace specula::scene::file
