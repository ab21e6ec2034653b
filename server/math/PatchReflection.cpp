#include "math/PatchReflection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace specula::math {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// How far from bisecting a grid sample's normal may be and still start a Newton solve: a sample
// grid of 12 a side leaves neighbouring normals a few degrees apart on smooth patches.
constexpr double kStartCosine = 0.9;

// The half vector of eye and vertex seen from S (not normalized): unit direction to the eye plus
// unit direction to the vertex. S is a reflection point exactly when it is parallel to the normal.
glm::dvec3 halfVector(const glm::dvec3& s, const glm::dvec3& eye, const glm::dvec3& vertex) {
  return glm::normalize(eye - s) + glm::normalize(vertex - s);
}

// The (u, v) of `patch` nearest `point`, by Newton's method on (S − p)·Su = (S − p)·Sv = 0 from
// `uv`, kept on the patch.
glm::dvec2 project(const BezierPatch& patch, glm::dvec2 uv, const glm::dvec3& point) {
  for (int iteration = 0; iteration < 20; ++iteration) {
    const PatchSample s = patch.sample(uv.x, uv.y);
    const glm::dvec3 d = s.position - point;
    // Gauss-Newton: the surface's metric, without the second derivatives' small terms.
    const glm::dmat2 metric(glm::dot(s.du, s.du), glm::dot(s.du, s.dv), glm::dot(s.du, s.dv), glm::dot(s.dv, s.dv));
    if (!(std::abs(glm::determinant(metric)) > 1e-300)) break;
    const glm::dvec2 step = glm::inverse(metric) * -glm::dvec2(glm::dot(d, s.du), glm::dot(d, s.dv));
    uv = glm::clamp(uv + step, 0.0, 1.0);
    if (glm::length(step) < 1e-12) break;
  }
  return uv;
}

}  // namespace

PatchReflectionSolver::PatchReflectionSolver(std::vector<BezierPatch> patches, int samplesPerSide)
    : patches_(std::move(patches)), side_(std::max(2, samplesPerSide)) {
  samples_.reserve(patches_.size() * static_cast<std::size_t>(side_ * side_));
  for (const BezierPatch& patch : patches_)
    for (int j = 0; j < side_; ++j)
      for (int i = 0; i < side_; ++i) samples_.push_back(patch.sample((i + 0.5) / side_, (j + 0.5) / side_));
}

std::optional<PatchPoint> PatchReflectionSolver::refine(std::size_t patch, glm::dvec2 uv, const glm::dvec3& eye,
                                                        const glm::dvec3& vertex) const {
  const BezierPatch& p = patches_[patch];
  // G(u, v) = (H·Su, H·Sv) vanishes exactly where H ∥ N; its Jacobian by central differences.
  const auto g = [&](const glm::dvec2& at) {
    const PatchSample s = p.sample(at.x, at.y);
    const glm::dvec3 h = halfVector(s.position, eye, vertex);
    return glm::dvec2(glm::dot(h, s.du), glm::dot(h, s.dv));
  };
  constexpr double kStep = 1e-6;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const PatchSample s = p.sample(uv.x, uv.y);
    const glm::dvec3 h = halfVector(s.position, eye, vertex);
    const double hLength = glm::length(h);
    if (!(hLength > 1e-12)) return std::nullopt;  // eye and vertex in opposite directions: grazing
    if (glm::length(glm::cross(h / hLength, s.normal)) < 1e-13) {
      if (uv.x < -1e-9 || uv.x > 1.0 + 1e-9 || uv.y < -1e-9 || uv.y > 1.0 + 1e-9) return std::nullopt;
      if (glm::dot(s.normal, eye - s.position) <= 0.0 || glm::dot(s.normal, vertex - s.position) <= 0.0)
        return std::nullopt;
      return PatchPoint{patch, glm::clamp(uv, 0.0, 1.0), s.position, s.normal};
    }
    const glm::dvec2 value(glm::dot(h, s.du), glm::dot(h, s.dv));
    const glm::dvec2 dgdu = (g(uv + glm::dvec2(kStep, 0.0)) - g(uv - glm::dvec2(kStep, 0.0))) / (2.0 * kStep);
    const glm::dvec2 dgdv = (g(uv + glm::dvec2(0.0, kStep)) - g(uv - glm::dvec2(0.0, kStep))) / (2.0 * kStep);
    const glm::dmat2 jacobian(dgdu, dgdv);
    const double determinant = glm::determinant(jacobian);
    if (!(std::abs(determinant) > 1e-300)) return std::nullopt;
    glm::dvec2 step = glm::inverse(jacobian) * -value;
    // Damped: a step longer than a quarter patch is cut down, so the iteration cannot leap patches.
    const double length = glm::length(step);
    if (length > 0.25) step *= 0.25 / length;
    uv += step;
    if (!(uv.x > -0.25 && uv.x < 1.25 && uv.y > -0.25 && uv.y < 1.25)) return std::nullopt;
  }
  return std::nullopt;
}

std::optional<PatchPoint> PatchReflectionSolver::solveNear(const glm::dvec3& eye, const glm::dvec3& vertex,
                                                           const glm::dvec3& near) const {
  if (!finite(eye) || !finite(vertex) || !finite(near) || samples_.empty()) return std::nullopt;
  // `near` by a seam may lie on the patch next to the one whose sample is nearest: Newton starts
  // on each of the few nearest patches, from the (u, v) nearest `near` (its sample, then projected:
  // two solutions a sample's spacing apart by a fold would otherwise draw it to the wrong one), and
  // the solution nearest `near` wins.
  constexpr std::size_t kPatchesTried = 4;
  const auto perPatch = static_cast<std::size_t>(side_ * side_);
  std::vector<std::pair<double, std::size_t>> nearestOfPatch;  // distance, sample index
  for (std::size_t patch = 0; patch < patches_.size(); ++patch) {
    std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), 0};
    for (std::size_t i = patch * perPatch; i < (patch + 1) * perPatch; ++i)
      best = std::min(best, std::pair{glm::length(samples_[i].position - near), i});
    nearestOfPatch.push_back(best);
  }
  const std::size_t tried = std::min(kPatchesTried, nearestOfPatch.size());
  std::partial_sort(nearestOfPatch.begin(), nearestOfPatch.begin() + static_cast<std::ptrdiff_t>(tried),
                    nearestOfPatch.end());
  std::optional<PatchPoint> found;
  for (std::size_t k = 0; k < tried; ++k) {
    const std::size_t sample = nearestOfPatch[k].second;
    const auto inPatch = static_cast<int>(sample % perPatch);
    const std::size_t patch = sample / perPatch;
    const glm::dvec2 start =
        project(patches_[patch], {(inPatch % side_ + 0.5) / side_, (inPatch / side_ + 0.5) / side_}, near);
    const auto point = refine(patch, start, eye, vertex);
    if (point && (!found || glm::length(point->position - near) < glm::length(found->position - near))) found = point;
  }
  return found;
}

std::vector<PatchPoint> PatchReflectionSolver::solve(const glm::dvec3& eye, const glm::dvec3& vertex) const {
  std::vector<PatchPoint> found;
  if (!finite(eye) || !finite(vertex)) return found;
  const auto cosine = [&](std::size_t index) {
    const PatchSample& s = samples_[index];
    const glm::dvec3 h = halfVector(s.position, eye, vertex);
    const double length = glm::length(h);
    return length > 1e-12 ? glm::dot(h, s.normal) / length : -1.0;
  };
  const auto perPatch = static_cast<std::size_t>(side_ * side_);
  for (std::size_t patch = 0; patch < patches_.size(); ++patch) {
    const std::size_t base = patch * perPatch;
    for (int j = 0; j < side_; ++j)
      for (int i = 0; i < side_; ++i) {
        const std::size_t index = base + static_cast<std::size_t>(j * side_ + i);
        const double c = cosine(index);
        if (c < kStartCosine) continue;
        // Start only from local bests of the grid (ties go to the first), so one solution is not solved many times.
        bool best = true;
        for (int dj = -1; dj <= 1 && best; ++dj)
          for (int di = -1; di <= 1 && best; ++di) {
            const int ni = i + di, nj = j + dj;
            if ((di == 0 && dj == 0) || ni < 0 || nj < 0 || ni >= side_ || nj >= side_) continue;
            const double other = cosine(base + static_cast<std::size_t>(nj * side_ + ni));
            best = other < c || (other == c && (nj > j || (nj == j && ni > i)));
          }
        if (!best) continue;
        const auto point = refine(patch, {(i + 0.5) / side_, (j + 0.5) / side_}, eye, vertex);
        if (!point) continue;
        const double scale = glm::length(point->position - eye) + 1.0;
        const bool duplicate = std::any_of(found.begin(), found.end(), [&](const PatchPoint& other) {
          return glm::length(other.position - point->position) < 1e-7 * scale;
        });
        if (!duplicate) found.push_back(*point);
      }
  }
  std::sort(found.begin(), found.end(), [&](const PatchPoint& a, const PatchPoint& b) {
    return glm::length(a.position - eye) < glm::length(b.position - eye);
  });
  return found;
}

}  // namespace specula::math
