#include "reference/PatchSurface.h"

#include "math/RayBox.h"

namespace specula::reference {

PatchSurface::PatchSurface(const std::vector<math::BezierPatch>& objectPatches, const glm::mat4& objectToWorld) {
  const glm::dmat4 toWorld(objectToWorld);
  glm::dvec3 low(1e300), high(-1e300);
  constexpr double kPiece = 1.0 / kPiecesPerSide;
  for (std::size_t p = 0; p < objectPatches.size(); ++p) {
    patches_.push_back(objectPatches[p].transformed(toWorld));
    for (int j = 0; j < kPiecesPerSide; ++j)
      for (int i = 0; i < kPiecesPerSide; ++i) {
        const glm::dvec2 corner(i * kPiece, j * kPiece);
        pieces_.push_back(
            {patches_.back().restricted(corner.x, corner.x + kPiece, corner.y, corner.y + kPiece), p, corner});
      }
    const auto [patchLow, patchHigh] = patches_.back().controlBounds();
    low = glm::min(low, patchLow);
    high = glm::max(high, patchHigh);
  }
  selfHitDistance_ = 1e-6 * (patches_.empty() ? 1.0 : glm::length(high - low));
}

std::optional<PatchSurfaceHit> PatchSurface::intersectPiece(std::size_t piece, const glm::dvec3& origin,
                                                            const glm::dvec3& direction, double tMin,
                                                            double tMax) const {
  const Piece& p = pieces_[piece];
  const auto hit = math::intersectPatch(p.bezier, origin, direction, tMin, tMax);
  if (!hit) return std::nullopt;
  return PatchSurfaceHit{hit->t, p.patch, p.low + hit->uv / static_cast<double>(kPiecesPerSide)};
}

bool PatchSurface::meetsBefore(const glm::dvec3& origin, const glm::dvec3& direction, double tMax) const {
  const glm::dvec3 inverse = 1.0 / direction;
  for (std::size_t piece = 0; piece < pieces_.size(); ++piece) {
    const auto [low, high] = pieceBounds(piece);
    if (math::rayMeetsBox(low, high, origin, inverse, 0.0, tMax) && intersectPiece(piece, origin, direction, 0.0, tMax))
      return true;
  }
  return false;
}

}  // namespace specula::reference
