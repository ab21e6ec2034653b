#include "math/BSplineSurface.h"

#include <array>
#include <cmath>

namespace specula::math {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

using Points = std::array<glm::dvec3, 4>;

// The blossom of the degree-p curve piece on knot span `span` (points[0..p] are control points
// span−p … span) at the p arguments `args`: de Boor's algorithm with one argument per level.
glm::dvec3 blossom(const std::vector<double>& knots, int p, int span, Points points,
                   const std::array<double, 3>& args) {
  for (int r = 1; r <= p; ++r)
    for (int i = p; i >= r; --i) {
      const auto j = static_cast<std::size_t>(span - p + i);
      const double alpha = (args[static_cast<std::size_t>(r - 1)] - knots[j]) /
                           (knots[j + static_cast<std::size_t>(p + 1 - r)] - knots[j]);
      points[static_cast<std::size_t>(i)] =
          (1.0 - alpha) * points[static_cast<std::size_t>(i - 1)] + alpha * points[static_cast<std::size_t>(i)];
    }
  return points[static_cast<std::size_t>(p)];
}

// The cubic Bézier points of a degree-p curve piece over its span: Bézier point k of [a, b] is the
// blossom at (a × (p − k), b × k); then degree-raised to 3 (exact: the same polynomial).
Points cubicBezierOfSpan(const std::vector<double>& knots, int p, int span, const Points& points) {
  const double a = knots[static_cast<std::size_t>(span)], b = knots[static_cast<std::size_t>(span + 1)];
  Points bezier{};
  for (int k = 0; k <= p; ++k) {
    std::array<double, 3> args{};
    for (int level = 0; level < p; ++level) args[static_cast<std::size_t>(level)] = level < p - k ? a : b;
    bezier[static_cast<std::size_t>(k)] = blossom(knots, p, span, points, args);
  }
  for (int n = p; n < 3; ++n) {  // degree n → n + 1
    Points raised{};
    for (int i = 0; i <= n + 1; ++i) {
      const double w = static_cast<double>(i) / (n + 1);
      raised[static_cast<std::size_t>(i)] =
          (i > 0 ? w * bezier[static_cast<std::size_t>(i - 1)] : glm::dvec3(0.0)) +
          (i <= n ? (1.0 - w) * bezier[static_cast<std::size_t>(i)] : glm::dvec3(0.0));
    }
    bezier = raised;
  }
  return bezier;
}

std::optional<std::string> knotProblem(const std::vector<double>& knots, int degree, int count, const char* name) {
  const std::size_t expected = static_cast<std::size_t>(count + degree + 1);
  if (knots.size() != expected)
    return std::string(name) + " has " + std::to_string(knots.size()) + " knots; " + std::to_string(count) +
           " control points of degree " + std::to_string(degree) +
           " need count + degree + 1 = " + std::to_string(expected);
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) return std::string(name) + "[" + std::to_string(i) + "] is not a finite number";
    if (i > 0 && knots[i] < knots[i - 1])
      return std::string(name) + " must not decrease, but knot " + std::to_string(i) + " is less than the one before";
  }
  if (!(knots[static_cast<std::size_t>(degree)] < knots[static_cast<std::size_t>(count)]))
    return std::string(name) + " leaves the surface no domain: knots[degree] must be less than knots[count]";
  return std::nullopt;
}

int nonEmptySpans(const std::vector<double>& knots, int degree, int count) {
  int spans = 0;
  for (int s = degree; s < count; ++s)
    spans += knots[static_cast<std::size_t>(s)] < knots[static_cast<std::size_t>(s + 1)];
  return spans;
}

}  // namespace

std::optional<std::string> bsplineProblem(const BSplineSurface& surface) {
  for (int axis = 0; axis < 2; ++axis) {
    const char* name = axis == 0 ? "u" : "v";
    const int degree = surface.degree[axis], count = surface.count[axis];
    if (degree < 1 || degree > BSplineSurface::kMaxDegree)
      return std::string("degree along ") + name + " is " + std::to_string(degree) + "; use 1, 2 or 3";
    if (count < degree + 1 || count > 4096)
      return std::string("count along ") + name + " is " + std::to_string(count) + "; degree " +
             std::to_string(degree) + " needs from " + std::to_string(degree + 1) + " to 4096 control points";
  }
  const std::size_t points = static_cast<std::size_t>(surface.count.x) * static_cast<std::size_t>(surface.count.y);
  if (surface.controlNet.size() != points)
    return "the control net has " + std::to_string(surface.controlNet.size()) + " points; count " +
           std::to_string(surface.count.x) + " x " + std::to_string(surface.count.y) + " needs " +
           std::to_string(points);
  for (std::size_t i = 0; i < surface.controlNet.size(); ++i)
    if (!finite(surface.controlNet[i])) return "control point " + std::to_string(i) + " is not finite";
  if (auto problem = knotProblem(surface.knotsU, surface.degree.x, surface.count.x, "knots along u")) return problem;
  if (auto problem = knotProblem(surface.knotsV, surface.degree.y, surface.count.y, "knots along v")) return problem;
  const std::size_t patches =
      static_cast<std::size_t>(nonEmptySpans(surface.knotsU, surface.degree.x, surface.count.x)) *
      static_cast<std::size_t>(nonEmptySpans(surface.knotsV, surface.degree.y, surface.count.y));
  if (patches > BSplineSurface::kMaxPatches)
    return "the surface has " + std::to_string(patches) + " knot spans, more than the " +
           std::to_string(BSplineSurface::kMaxPatches) + " patches a surface may have; use fewer control points";
  return std::nullopt;
}

std::vector<BezierPatch> bezierPatchesOf(const BSplineSurface& surface) {
  const glm::ivec2 p = surface.degree, n = surface.count;
  std::vector<BezierPatch> patches;
  for (int sv = p.y; sv < n.y; ++sv) {
    if (!(surface.knotsV[static_cast<std::size_t>(sv)] < surface.knotsV[static_cast<std::size_t>(sv + 1)])) continue;
    for (int su = p.x; su < n.x; ++su) {
      if (!(surface.knotsU[static_cast<std::size_t>(su)] < surface.knotsU[static_cast<std::size_t>(su + 1)])) continue;
      // Along u, row by row, for the p.y + 1 rows of this span; then along v, column by column.
      std::array<Points, 4> rows{};
      for (int r = 0; r <= p.y; ++r) {
        Points span{};
        for (int i = 0; i <= p.x; ++i)
          span[static_cast<std::size_t>(i)] =
              surface.controlNet[static_cast<std::size_t>((sv - p.y + r) * n.x + (su - p.x + i))];
        rows[static_cast<std::size_t>(r)] = cubicBezierOfSpan(surface.knotsU, p.x, su, span);
      }
      BezierPatch patch;
      for (int column = 0; column < 4; ++column) {
        Points span{};
        for (int r = 0; r <= p.y; ++r)
          span[static_cast<std::size_t>(r)] = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(column)];
        const Points bezier = cubicBezierOfSpan(surface.knotsV, p.y, sv, span);
        for (int row = 0; row < 4; ++row)
          patch.points[static_cast<std::size_t>(4 * row + column)] = bezier[static_cast<std::size_t>(row)];
      }
      patches.push_back(patch);
    }
  }
  return patches;
}

}  // namespace specula::math
