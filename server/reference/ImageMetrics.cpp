#include "reference/ImageMetrics.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace specula::reference {

namespace {

constexpr int kWindow = 11;  // Gaussian SSIM window side, σ = kSigma
constexpr double kSigma = 1.5;

std::string sizeText(const RgbaView& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

std::size_t pixelCount(const RgbaView& image) {
  return static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
}

Status sameSize(const char* metric, const RgbaView& a, const RgbaView& b) {
  assert(a.rgba.size() == pixelCount(a) * 4 && b.rgba.size() == pixelCount(b) * 4);
  if (a.width != b.width || a.height != b.height)
    return Error{std::string(metric) + "(): image sizes differ (" + sizeText(a) + " vs " + sizeText(b) +
                 "); render both images at the same size"};
  return {};
}

// BT.601 luma, as the reference SSIM implementation takes from RGB (unrounded here).
std::vector<double> luma(const RgbaView& image) {
  std::vector<double> y(pixelCount(image));
  for (std::size_t i = 0; i < y.size(); ++i) {
    const std::uint8_t* p = &image.rgba[4 * i];
    y[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
  }
  return y;
}

std::array<double, kWindow> gaussianWeights() {
  std::array<double, kWindow> weights{};
  double sum = 0.0;
  for (int i = 0; i < kWindow; ++i) {
    const double x = i - kWindow / 2;
    weights[static_cast<std::size_t>(i)] = std::exp(-x * x / (2.0 * kSigma * kSigma));
    sum += weights[static_cast<std::size_t>(i)];
  }
  for (double& w : weights) w /= sum;
  return weights;
}

// One pass of the separable Gaussian, along x or y, at every position where the window fits ("valid"
// filtering): the plane shrinks by kWindow − 1 along that axis.
std::vector<double> gaussianPass(const std::vector<double>& plane, int width, int height, bool alongX) {
  static const std::array<double, kWindow> weights = gaussianWeights();
  const auto outWidth = static_cast<std::size_t>(alongX ? width - kWindow + 1 : width);
  const auto outHeight = static_cast<std::size_t>(alongX ? height : height - kWindow + 1);
  const std::size_t step = alongX ? 1 : static_cast<std::size_t>(width);
  std::vector<double> out(outWidth * outHeight, 0.0);
  for (std::size_t y = 0; y < outHeight; ++y)
    for (std::size_t x = 0; x < outWidth; ++x)
      for (std::size_t k = 0; k < weights.size(); ++k)
        out[y * outWidth + x] += weights[k] * plane[y * static_cast<std::size_t>(width) + x + k * step];
  return out;
}

// Gaussian-weighted means of the 11×11 windows lying wholly inside a width × height plane.
std::vector<double> windowMeans(const std::vector<double>& plane, int width, int height) {
  return gaussianPass(gaussianPass(plane, width, height, true), width - kWindow + 1, height, false);
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> result(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) result[i] = a[i] * b[i];
  return result;
}

}  // namespace

Result<double> psnr(const RgbaView& a, const RgbaView& b) {
  if (Status same = sameSize("psnr", a, b); !same) return Error{same.error()};
  std::uint64_t squaredErrors = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha
    const int difference = a.rgba[i] - b.rgba[i];
    squaredErrors += static_cast<std::uint64_t>(difference * difference);
  }
  if (squaredErrors == 0) return std::numeric_limits<double>::infinity();
  const double meanSquaredError = static_cast<double>(squaredErrors) / (3.0 * static_cast<double>(pixelCount(a)));
  return 10.0 * std::log10(255.0 * 255.0 / meanSquaredError);
}

Result<double> ssim(const RgbaView& a, const RgbaView& b) {
  if (Status same = sameSize("ssim", a, b); !same) return Error{same.error()};
  if (a.width < kWindow || a.height < kWindow)
    return Error{"ssim(): image size " + sizeText(a) + " is smaller than the 11x11 SSIM window; compare larger images"};
  const std::vector<double> x = luma(a), y = luma(b);
  const int w = a.width, h = a.height;
  const std::vector<double> meanX = windowMeans(x, w, h), meanY = windowMeans(y, w, h);
  const std::vector<double> meanXX = windowMeans(product(x, x), w, h), meanYY = windowMeans(product(y, y), w, h),
                            meanXY = windowMeans(product(x, y), w, h);
  constexpr double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);
  double sum = 0.0;
  for (std::size_t i = 0; i < meanX.size(); ++i) {
    const double mx = meanX[i], my = meanY[i];
    const double varianceX = meanXX[i] - mx * mx, varianceY = meanYY[i] - my * my, covariance = meanXY[i] - mx * my;
    sum += ((2.0 * mx * my + c1) * (2.0 * covariance + c2)) / ((mx * mx + my * my + c1) * (varianceX + varianceY + c2));
  }
  return sum / static_cast<double>(meanX.size());
}

Result<MaskedMismatch> maskedMismatch(const RgbaView& a, const RgbaView& b, std::span<const std::uint8_t> mask,
                                      int threshold) {
  if (Status same = sameSize("maskedMismatch", a, b); !same) return Error{same.error()};
  if (mask.size() != pixelCount(a))
    return Error{"maskedMismatch(): the mask has " + std::to_string(mask.size()) + " entries for a " + sizeText(a) +
                 " image; pass one mask byte per pixel"};
  MaskedMismatch result;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (mask[i] == 0) continue;
    ++result.inside;
    if (pixelsMismatch(&a.rgba[4 * i], &b.rgba[4 * i], threshold)) ++result.mismatched;
  }
  return result;
}

}  // namespace specula::reference
