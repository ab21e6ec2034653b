#pragma once
// Tensor-product B-spline surfaces, converted into the bicubic Bézier patches everything else uses:
// every non-empty knot span pair becomes one patch (blossoming), lower degrees are raised to 3 exactly.
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "math/BezierPatch.h"

namespace specula::math {

struct BSplineSurface {
  glm::ivec2 degree{3, 3};             // along u, along v; 1, 2 or 3 each
  glm::ivec2 count{4, 4};              // control points along u (a row) and along v (rows)
  std::vector<double> knotsU, knotsV;  // count + degree + 1 each, non-decreasing
  std::vector<glm::dvec3> controlNet;  // count.y rows of count.x points, row-major

  static constexpr int kMaxDegree = 3;
  static constexpr std::size_t kMaxPatches = 4096;
};

// What is wrong with the surface, in words that name the field and the fix; nullopt when it is valid.
std::optional<std::string> bsplineProblem(const BSplineSurface& surface);

// The surface as bicubic Bézier patches over its valid domain [knots[degree], knots[count]], one per
// non-empty span pair, row-major over v then u spans. The surface must pass bsplineProblem().
std::vector<BezierPatch> bezierPatchesOf(const BSplineSurface& surface);

}  // namespace specula::math
