#pragma once
// Comparison of a rendered image with a reference: PSNR, SSIM and the share of strongly wrong pixels
// inside a mask (the mirrors). Every metric reads R, G and B and ignores alpha.
#include <cstddef>
#include <cstdint>
#include <span>

#include "base/Result.h"

namespace specula::reference {

// Borrowed RGBA8 pixels, tightly packed, row 0 at the top; rgba.size() == width · height · 4.
struct RgbaView {
  std::span<const std::uint8_t> rgba;
  int width = 0;
  int height = 0;
};

// Peak signal-to-noise ratio in dB: 10 · log10(255² / MSE), the mean squared error taken over the R, G
// and B bytes of every pixel. Identical images give +infinity. Fails when the sizes differ.
Result<double> psnr(const RgbaView& a, const RgbaView& b);

// Structural similarity (Wang, Bovik, Sheikh & Simoncelli 2004) of the luma Y = 0.299 R + 0.587 G +
// 0.114 B: the mean SSIM over every position of an 11×11 Gaussian window (σ = 1.5) lying wholly inside
// the image, K1 = 0.01, K2 = 0.03, L = 255, no downsampling. 1 for identical images; lower is worse
// (negative for anti-correlated structure). Fails when the sizes differ or either side is below 11.
Result<double> ssim(const RgbaView& a, const RgbaView& b);

// A pixel mismatches when some channel of R, G, B differs by more than the threshold (in bytes). The
// default, 16 of 255, lets rounding and small shading differences pass but not a wrong object or
// checker cell, or a missing reflection.
inline constexpr int kDefaultMismatchThreshold = 16;

// Whether two RGBA pixels mismatch: some channel of R, G, B differs by more than `threshold`.
inline bool pixelsMismatch(const std::uint8_t* a, const std::uint8_t* b, int threshold) {
  for (int c = 0; c < 3; ++c)
    if (a[c] - b[c] > threshold || b[c] - a[c] > threshold) return true;
  return false;
}

struct MaskedMismatch {
  std::size_t inside = 0;      // pixels with a non-zero mask entry
  std::size_t mismatched = 0;  // of those, the ones that mismatch
  // mismatched / inside; 0 when the mask is empty (nothing inside can be wrong).
  double share() const { return inside == 0 ? 0.0 : static_cast<double>(mismatched) / static_cast<double>(inside); }
};

// Counts mismatching pixels where `mask` (one byte per pixel, row 0 at the top) is non-zero.
// Fails when the image sizes differ or the mask does not have one entry per pixel.
Result<MaskedMismatch> maskedMismatch(const RgbaView& a, const RgbaView& b, std::span<const std::uint8_t> mask,
                                      int threshold = kDefaultMismatchThreshold);

}  // namespace specula::reference
