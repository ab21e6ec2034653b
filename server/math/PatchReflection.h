#pragma once
// Exact reflection points on a surface of Bézier patches, the reference that searched reflection
// points on parametric mirrors are measured against: every surface point S whose normal bisects the
// directions to the eye and the vertex, found by Newton's method on (u, v) from the local best of a
// grid of samples, to double precision.
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "math/BezierPatch.h"

namespace specula::math {

struct PatchPoint {
  std::size_t patch = 0;
  glm::dvec2 uv{0.0};
  glm::dvec3 position{0.0};
  glm::dvec3 normal{0.0};  // unit, the patch's front side
};

class PatchReflectionSolver {
 public:
  // `patches` in the space eye and vertices are given in (world, for a posed mirror).
  explicit PatchReflectionSolver(std::vector<BezierPatch> patches, int samplesPerSide = 12);

  // Every reflection point with eye and vertex both in front of the surface there, nearest the eye
  // first; empty when the vertex has no reflection (or eye or vertex is not finite).
  std::vector<PatchPoint> solve(const glm::dvec3& eye, const glm::dvec3& vertex) const;
  // The reflection point nearest `near` (a point on or by the surface) that Newton's method reaches
  // from `near`'s projection on each of the four patches nearest it, if any converges on its patch: a
  // solution the grid's starts can miss (two close together, or one by a patch's edge) found where
  // another method put it.
  std::optional<PatchPoint> solveNear(const glm::dvec3& eye, const glm::dvec3& vertex, const glm::dvec3& near) const;
  // The reflection point Newton's method reaches from (patch, uv), if it converges on that patch.
  std::optional<PatchPoint> refine(std::size_t patch, glm::dvec2 uv, const glm::dvec3& eye,
                                   const glm::dvec3& vertex) const;

  const std::vector<BezierPatch>& patches() const { return patches_; }

 private:
  std::vector<BezierPatch> patches_;
  int side_;
  std::vector<PatchSample> samples_;  // side_² per patch, row-major over v then u
};

}  // namespace specula::math
