#include "math/BezierPatch.h"

#include <algorithm>
#include <cmath>

namespace specula::math {

namespace {

// Cubic Bernstein basis and its derivative at t.
std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}
std::array<double, 4> bernsteinDerivative(double t) {
  const double s = 1.0 - t;
  return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

// The cubic with control points `c` restricted to [t0, t1], reparametrised to [0, 1].
std::array<glm::dvec3, 4> restrictCubic(std::array<glm::dvec3, 4> c, double t0, double t1) {
  // Split at t1 and keep the left part, then split that at t0 / t1 and keep the right part.
  const auto left = [](const std::array<glm::dvec3, 4>& p, double t) {
    const glm::dvec3 a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t), c2 = glm::mix(p[2], p[3], t);
    const glm::dvec3 d = glm::mix(a, b, t), e = glm::mix(b, c2, t);
    return std::array<glm::dvec3, 4>{p[0], a, d, glm::mix(d, e, t)};
  };
  const auto right = [](const std::array<glm::dvec3, 4>& p, double t) {
    const glm::dvec3 a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t), c2 = glm::mix(p[2], p[3], t);
    const glm::dvec3 d = glm::mix(a, b, t), e = glm::mix(b, c2, t);
    return std::array<glm::dvec3, 4>{glm::mix(d, e, t), e, c2, p[3]};
  };
  if (t1 < 1.0) c = left(c, t1);
  if (t0 > 0.0) c = right(c, t1 > 0.0 ? t0 / t1 : 0.0);
  return c;
}

}  // namespace

glm::dvec3 BezierPatch::position(double u, double v) const {
  const auto bu = bernstein(u), bv = bernstein(v);
  glm::dvec3 p(0.0);
  for (int row = 0; row < 4; ++row) {
    glm::dvec3 rowPoint(0.0);
    for (int column = 0; column < 4; ++column) rowPoint += bu[static_cast<std::size_t>(column)] * point(row, column);
    p += bv[static_cast<std::size_t>(row)] * rowPoint;
  }
  return p;
}

PatchSample BezierPatch::sample(double u, double v) const {
  const auto evaluate = [this](double su, double sv) {
    const auto bu = bernstein(su), bv = bernstein(sv), du = bernsteinDerivative(su), dv = bernsteinDerivative(sv);
    PatchSample s;
    for (int row = 0; row < 4; ++row)
      for (int column = 0; column < 4; ++column) {
        const glm::dvec3& p = point(row, column);
        const auto r = static_cast<std::size_t>(row), c = static_cast<std::size_t>(column);
        s.position += bu[c] * bv[r] * p;
        s.du += du[c] * bv[r] * p;
        s.dv += bu[c] * dv[r] * p;
      }
    return s;
  };
  PatchSample s = evaluate(u, v);
  const double scale = glm::length(s.du) + glm::length(s.dv);
  glm::dvec3 n = glm::cross(s.du, s.dv);
  // A collapsed edge (the teapot's lid and bottom poles) has no tangent plane of its own: take the
  // normal's limit by stepping towards the patch's centre, a little further each time.
  for (double step = 1e-7; glm::length(n) <= 1e-9 * scale * scale && step < 0.1; step *= 30.0) {
    const PatchSample inside = evaluate(u + (0.5 - u) * step, v + (0.5 - v) * step);
    n = glm::cross(inside.du, inside.dv);
  }
  const double length = glm::length(n);
  if (length > 0.0) s.normal = n / length;
  return s;
}

BezierPatch BezierPatch::transformed(const glm::dmat4& affine) const {
  BezierPatch out;
  for (std::size_t i = 0; i < points.size(); ++i) out.points[i] = glm::dvec3(affine * glm::dvec4(points[i], 1.0));
  return out;
}

BezierPatch BezierPatch::restricted(double u0, double u1, double v0, double v1) const {
  BezierPatch rowsDone;
  for (int row = 0; row < 4; ++row) {
    const auto c = restrictCubic({point(row, 0), point(row, 1), point(row, 2), point(row, 3)}, u0, u1);
    for (int column = 0; column < 4; ++column)
      rowsDone.points[static_cast<std::size_t>(4 * row + column)] = c[static_cast<std::size_t>(column)];
  }
  BezierPatch out;
  for (int column = 0; column < 4; ++column) {
    const auto c = restrictCubic(
        {rowsDone.point(0, column), rowsDone.point(1, column), rowsDone.point(2, column), rowsDone.point(3, column)},
        v0, v1);
    for (int row = 0; row < 4; ++row)
      out.points[static_cast<std::size_t>(4 * row + column)] = c[static_cast<std::size_t>(row)];
  }
  return out;
}

std::pair<glm::dvec3, glm::dvec3> BezierPatch::controlBounds() const {
  glm::dvec3 low = points[0], high = points[0];
  for (const glm::dvec3& p : points) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  return {low, high};
}

std::optional<PatchRayHit> intersectPatch(const BezierPatch& patch, const glm::dvec3& origin,
                                          const glm::dvec3& direction, double tMin, double tMax) {
  const auto [low, high] = patch.controlBounds();
  const double size = std::max(glm::length(high - low), 1e-300);
  const double slack = 1e-9;  // in u and v: a ray through a shared edge must hit one of its two patches
  const auto newton = [&](glm::dvec2 uv) -> std::optional<PatchRayHit> {
    double t = glm::dot(patch.position(uv.x, uv.y) - origin, direction) / glm::dot(direction, direction);
    for (int iteration = 0; iteration < 16; ++iteration) {
      const PatchSample s = patch.sample(uv.x, uv.y);
      const glm::dvec3 residual = s.position - (origin + t * direction);
      if (glm::length(residual) <= 1e-12 * size) {
        if (uv.x < -slack || uv.x > 1.0 + slack || uv.y < -slack || uv.y > 1.0 + slack) return std::nullopt;
        if (!(t > tMin && t < tMax)) return std::nullopt;
        return PatchRayHit{t, glm::clamp(uv, 0.0, 1.0)};
      }
      // Solve [du dv −direction]·(Δu, Δv, Δt) = −residual.
      const glm::dmat3 jacobian(s.du, s.dv, -direction);
      const double determinant = glm::determinant(jacobian);
      if (!(std::abs(determinant) > 1e-300)) return std::nullopt;
      const glm::dvec3 step = glm::inverse(jacobian) * -residual;
      uv += glm::dvec2(step.x, step.y);
      t += step.z;
      // A root far outside is another patch's business; stop before the cubic's tails run away.
      if (!(std::abs(uv.x - 0.5) < 2.0 && std::abs(uv.y - 0.5) < 2.0)) return std::nullopt;
    }
    return std::nullopt;
  };
  if (auto hit = newton({0.5, 0.5})) return hit;
  std::optional<PatchRayHit> nearest;
  for (const glm::dvec2 start :
       {glm::dvec2(0.25, 0.25), glm::dvec2(0.75, 0.25), glm::dvec2(0.25, 0.75), glm::dvec2(0.75, 0.75)})
    if (auto hit = newton(start); hit && (!nearest || hit->t < nearest->t)) nearest = hit;
  return nearest;
}

std::size_t patchGridTriangle(std::size_t patch, const glm::dvec2& uv, int segments) {
  const glm::dvec2 cell = uv * static_cast<double>(segments);
  const glm::ivec2 quad = glm::clamp(glm::ivec2(glm::floor(cell)), glm::ivec2(0), glm::ivec2(segments - 1));
  const glm::dvec2 inQuad = cell - glm::dvec2(quad);
  const auto quads = static_cast<std::size_t>(segments) * static_cast<std::size_t>(segments);
  // Quad (i, j) holds (a, b, d) below its diagonal and (a, d, c) above it (tessellatePatchGrid).
  return 2 * (patch * quads + static_cast<std::size_t>(quad.y * segments + quad.x)) + (inQuad.x < inQuad.y ? 1 : 0);
}

PatchGrid tessellatePatchGrid(const std::vector<BezierPatch>& patches, int segments) {
  PatchGrid grid;
  const auto side = static_cast<std::uint32_t>(segments + 1);
  for (const BezierPatch& patch : patches) {
    const auto base = static_cast<std::uint32_t>(grid.positions.size());
    for (int j = 0; j <= segments; ++j)
      for (int i = 0; i <= segments; ++i) {
        const glm::dvec2 uv(static_cast<double>(i) / segments, static_cast<double>(j) / segments);
        const PatchSample s = patch.sample(uv.x, uv.y);
        grid.positions.push_back(s.position);
        grid.normals.push_back(s.normal);
        grid.uvs.push_back(uv);
      }
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(segments); ++j)
      for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(segments); ++i) {
        const std::uint32_t a = base + j * side + i, b = a + 1, c = a + side, d = c + 1;
        // Counter-clockwise seen from where du × dv points.
        grid.indices.insert(grid.indices.end(), {a, b, d, a, d, c});
      }
  }
  return grid;
}

}  // namespace specula::math
