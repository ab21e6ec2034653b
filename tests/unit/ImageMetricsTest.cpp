#include "reference/ImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace specula::reference;

namespace {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  RgbaView view() const { return {rgba, width, height}; }
  std::uint8_t* at(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image{width, height, {}};
  for (int i = 0; i < width * height; ++i) image.rgba.insert(image.rgba.end(), {r, g, b, 255});
  return image;
}

// Bytes in [20, 235], so a ±16 change never clips.
Image noise(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> byte(20, 235);
  Image image = filled(width, height, 0, 0, 0);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    if (i % 4 != 3) image.rgba[i] = static_cast<std::uint8_t>(byte(random));
  return image;
}

// Smooth structure (a gradient with a bright disc), the kind of content SSIM is meant for.
Image picture(int width, int height) {
  Image image = filled(width, height, 0, 0, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool disc = (x - 20) * (x - 20) + (y - 15) * (y - 15) < 100;
      const auto value = static_cast<std::uint8_t>(disc ? 240 : 30 + 3 * x);
      std::uint8_t* p = image.at(x, y);
      p[0] = p[1] = p[2] = value;
    }
  return image;
}

Image inverted(Image image) {
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    if (i % 4 != 3) image.rgba[i] = static_cast<std::uint8_t>(255 - image.rgba[i]);
  return image;
}

TEST(ImageMetrics, PsnrOfIdenticalImagesIsInfinite) {
  const Image a = noise(17, 9, 1);
  auto value = psnr(a.view(), a.view());
  ASSERT_TRUE(value) << value.error();
  EXPECT_EQ(*value, std::numeric_limits<double>::infinity());
}

TEST(ImageMetrics, PsnrOfKnownErrorsMatchesTheFormulaAndIgnoresAlpha) {
  const Image a = noise(17, 9, 2);
  Image b = a;
  // Every pixel: R + 3, G − 4, B unchanged, alpha scrambled: MSE = (9 + 16 + 0) / 3.
  for (std::size_t i = 0; i < b.rgba.size(); i += 4) {
    b.rgba[i] = static_cast<std::uint8_t>(b.rgba[i] + 3);
    b.rgba[i + 1] = static_cast<std::uint8_t>(b.rgba[i + 1] - 4);
    b.rgba[i + 3] = static_cast<std::uint8_t>(i);
  }
  auto value = psnr(a.view(), b.view());
  ASSERT_TRUE(value) << value.error();
  EXPECT_NEAR(*value, 10.0 * std::log10(255.0 * 255.0 / (25.0 / 3.0)), 1e-12);
}

TEST(ImageMetrics, SsimOfIdenticalImagesIsExactlyOne) {
  const Image a = noise(40, 30, 3);
  auto value = ssim(a.view(), a.view());
  ASSERT_TRUE(value) << value.error();
  EXPECT_DOUBLE_EQ(*value, 1.0);
}

TEST(ImageMetrics, SsimOfTwoFlatImagesIsTheLuminanceTerm) {
  // No variance anywhere: contrast and structure terms are C2 / C2 = 1, leaving (2ab + C1) / (a² + b² + C1).
  const Image a = filled(20, 15, 100, 100, 100), b = filled(20, 15, 150, 150, 150);
  auto value = ssim(a.view(), b.view());
  ASSERT_TRUE(value) << value.error();
  const double c1 = (0.01 * 255) * (0.01 * 255);
  EXPECT_NEAR(*value, (2.0 * 100 * 150 + c1) / (100.0 * 100 + 150.0 * 150 + c1), 1e-9);
}

TEST(ImageMetrics, SsimOfAnInvertedImageIsLowAndOfASlightlyBrighterOneHigh) {
  const Image a = picture(64, 48);
  Image brighter = a;
  for (std::size_t i = 0; i < brighter.rgba.size(); ++i)
    if (i % 4 != 3) brighter.rgba[i] = static_cast<std::uint8_t>(brighter.rgba[i] + 5);
  auto invertedValue = ssim(a.view(), inverted(a).view());
  auto brighterValue = ssim(a.view(), brighter.view());
  ASSERT_TRUE(invertedValue && brighterValue);
  EXPECT_LT(*invertedValue, 0.0);  // anti-correlated structure
  EXPECT_GT(*brighterValue, 0.99);
  EXPECT_LT(*brighterValue, 1.0);
}

TEST(ImageMetrics, SsimRefusesImagesSmallerThanItsWindow) {
  const Image a = noise(10, 30, 4);
  auto value = ssim(a.view(), a.view());
  ASSERT_FALSE(value);
  EXPECT_NE(value.error().find("11x11"), std::string::npos) << value.error();
}

TEST(ImageMetrics, EveryMetricRefusesImagesOfDifferentSizes) {
  const Image a = noise(20, 20, 5), b = noise(20, 21, 5);
  const std::vector<std::uint8_t> mask(20 * 20, 1);
  auto p = psnr(a.view(), b.view());
  auto s = ssim(a.view(), b.view());
  auto m = maskedMismatch(a.view(), b.view(), mask);
  ASSERT_FALSE(p);
  ASSERT_FALSE(s);
  ASSERT_FALSE(m);
  for (const std::string& error : {p.error(), s.error(), m.error()})
    EXPECT_NE(error.find("20x20 vs 20x21"), std::string::npos) << error;
}

TEST(ImageMetrics, MaskedMismatchCountsPixelsBeyondTheThresholdInsideTheMaskOnly) {
  const Image a = noise(4, 3, 6);
  Image b = a;
  std::vector<std::uint8_t> mask(12, 0);
  const auto change = [&](int x, int y, int channel, int delta) {
    std::uint8_t& byte = b.at(x, y)[channel];
    byte = static_cast<std::uint8_t>(byte + delta);
  };
  for (int x = 0; x < 4; ++x) mask[static_cast<std::size_t>(4 + x)] = 1;  // the middle row: 4 pixels inside
  change(0, 1, 0, 16);                                                    // exactly the threshold: a match
  change(1, 1, 1, -17);                                                   // beyond it: a mismatch
  change(2, 1, 2, 17);                                                    // beyond it in blue alone: a mismatch
  change(3, 1, 3, 100);                                                   // alpha is not compared
  change(0, 0, 0, 100);                                                   // outside the mask
  change(3, 2, 1, -100);
  auto result = maskedMismatch(a.view(), b.view(), mask);
  ASSERT_TRUE(result) << result.error();
  EXPECT_EQ(result->inside, 4u);
  EXPECT_EQ(result->mismatched, 2u);
  EXPECT_DOUBLE_EQ(result->share(), 0.5);
  auto strict = maskedMismatch(a.view(), b.view(), mask, 0);
  ASSERT_TRUE(strict) << strict.error();
  EXPECT_EQ(strict->mismatched, 3u);
}

TEST(ImageMetrics, MaskedMismatchOfAnEmptyMaskIsZeroAndAShortMaskIsRefused) {
  const Image a = noise(4, 3, 7), b = inverted(a);
  auto none = maskedMismatch(a.view(), b.view(), std::vector<std::uint8_t>(12, 0));
  ASSERT_TRUE(none) << none.error();
  EXPECT_EQ(none->inside, 0u);
  EXPECT_EQ(none->share(), 0.0);
  auto shortMask = maskedMismatch(a.view(), b.view(), std::vector<std::uint8_t>(11, 1));
  ASSERT_FALSE(shortMask);
  EXPECT_NE(shortMask.error().find("one mask byte per pixel"), std::string::npos) << shortMask.error();
}

}  // namespace
