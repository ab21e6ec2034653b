#pragma once
// Bicubic Bézier patches: the one parametric surface form that scenes, the renderer, the ray tracer
// and the exact reflection solver share (B-spline surfaces are converted to it, math/BSplineSurface.h).
// Double precision throughout; affine maps act exactly on the control points.
#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace specula::math {

struct PatchSample {
  glm::dvec3 position{0.0};
  glm::dvec3 du{0.0}, dv{0.0};       // ∂S/∂u, ∂S/∂v
  glm::dvec3 normal{0.0, 1.0, 0.0};  // unit du × dv; on a collapsed edge (a pole) its limit from inside
};

// 16 control points, row-major: point(row, column) = points[4·row + column]. u runs along a row
// (over the columns), v over the rows; the patch's front faces where du × dv points.
struct BezierPatch {
  std::array<glm::dvec3, 16> points{};

  const glm::dvec3& point(int row, int column) const { return points[static_cast<std::size_t>(4 * row + column)]; }
  glm::dvec3 position(double u, double v) const;
  PatchSample sample(double u, double v) const;  // u, v in [0, 1]
  BezierPatch transformed(const glm::dmat4& affine) const;
  // The same surface over [u0, u1] × [v0, v1], reparametrised to [0, 1]² (de Casteljau): its control
  // points bound it tightly, which is what the ray tracer's hierarchy is built on.
  BezierPatch restricted(double u0, double u1, double v0, double v1) const;
  // Axis-aligned box of the control points, which contains the patch (convex hull property).
  std::pair<glm::dvec3, glm::dvec3> controlBounds() const;
};

struct PatchRayHit {
  double t = 0.0;
  glm::dvec2 uv{0.0};  // on the patch intersected
};

// Where origin + t·direction meets the patch for t in (tMin, tMax), by Newton's method on (u, v, t)
// from the patch's centre (and, should that fail to converge inside, from its four quarter points).
// Meant for small, nearly flat patches (BezierPatch::restricted pieces), where the root is unique;
// nullopt when none converges inside the patch.
std::optional<PatchRayHit> intersectPatch(const BezierPatch& patch, const glm::dvec3& origin,
                                          const glm::dvec3& direction, double tMin, double tMax);

// The patch every triangle of tessellatePatchGrid's layout belongs to, and the grid itself: each
// patch becomes an (n + 1)² vertex grid of exact samples (uv = (u, v) on its patch) and 2n² triangles,
// patch after patch, so triangle t lies on patch t / (2n²).
struct PatchGrid {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<glm::dvec2> uvs;
  std::vector<std::uint32_t> indices;
};
PatchGrid tessellatePatchGrid(const std::vector<BezierPatch>& patches, int segments);
// The triangle of that layout that (u, v) on patch `patch` falls in (mirror-gbuffer-patch.frag's
// gridTriangle is its GLSL twin).
std::size_t patchGridTriangle(std::size_t patch, const glm::dvec2& uv, int segments);

}  // namespace specula::math
