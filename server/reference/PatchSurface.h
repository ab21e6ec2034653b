#pragma once
// A parametric mirror's exact surface for the ray tracer: its Bézier patches in world space, cut
// into small pieces (tight boxes for Embree's hierarchy, one root each for Newton's method), so rays
// meet the surface itself and not the grid the rasterizer draws.
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "math/BezierPatch.h"

namespace specula::reference {

struct PatchSurfaceHit {
  double t = 0.0;
  std::size_t patch = 0;
  glm::dvec2 uv{0.0};  // on that patch
};

class PatchSurface {
 public:
  // Pieces per patch side: small enough that a ray crosses a piece at most once except at grazing.
  static constexpr int kPiecesPerSide = 8;

  PatchSurface(const std::vector<math::BezierPatch>& objectPatches, const glm::mat4& objectToWorld);

  std::size_t pieceCount() const { return pieces_.size(); }
  std::pair<glm::dvec3, glm::dvec3> pieceBounds(std::size_t piece) const {
    return pieces_[piece].bezier.controlBounds();
  }
  // Where the ray meets piece `piece` for t in (tMin, tMax).
  std::optional<PatchSurfaceHit> intersectPiece(std::size_t piece, const glm::dvec3& origin,
                                                const glm::dvec3& direction, double tMin, double tMax) const;
  // Whether the ray meets any piece for t in (0, tMax): every piece's box tested, no hierarchy (the
  // ray tracer has Embree's; this serves checks off the render path).
  bool meetsBefore(const glm::dvec3& origin, const glm::dvec3& direction, double tMax) const;
  math::PatchSample sample(const PatchSurfaceHit& hit) const { return patches_[hit.patch].sample(hit.uv.x, hit.uv.y); }
  // A distance below which a ray leaving the surface is taken to meet its own start again.
  double selfHitDistance() const { return selfHitDistance_; }

 private:
  struct Piece {
    math::BezierPatch bezier;  // the patch over its piece of [0, 1]²
    std::size_t patch = 0;
    glm::dvec2 low{0.0};  // the piece's corner in the patch's (u, v); it spans 1 / kPiecesPerSide
  };
  std::vector<math::BezierPatch> patches_;  // world
  std::vector<Piece> pieces_;
  double selfHitDistance_ = 0.0;
};

}  // namespace specula::reference
