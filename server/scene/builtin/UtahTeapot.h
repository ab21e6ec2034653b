#pragma once
// The Utah teapot: Martin Newell's 1975 teapot as 32 bicubic Bézier patches (rim, body, lid and
// bottom in four quarters, handle and spout in two halves), in its own units (about 3.15 tall and
// 6.4 long), y up, standing on y = 0 with its axis on the origin, spout towards +x. Fronts outwards.
#include <vector>

#include "math/BezierPatch.h"

namespace specula::scene::builtin {

std::vector<math::BezierPatch> utahTeapotPatches();

}  // namespace specula::scene::builtin
