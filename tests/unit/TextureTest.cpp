// Textures (issue #20): decoding refuses garbage by name, the mip chain averages in linear light, the
// reference's sampler follows GL's filtering and wrap rules; the anti-aliasing sample patterns.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "math/Color.h"
#include "math/SamplePattern.h"
#include "reference/TextureSampler.h"
#include "scene/Texture.h"

using namespace specula;
namespace fs = std::filesystem;

namespace {

const fs::path kAssets = fs::path(SPECULA_TEST_DATA_DIR) / "scenes";

std::string fileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A texture from rows of opaque sRGB bytes, row 0 first.
scene::Texture textureOf(int width, int height, const std::vector<std::array<std::uint8_t, 3>>& texels,
                         scene::TextureWrap wrap = scene::TextureWrap::Repeat) {
  std::vector<std::uint8_t> rgba;
  for (const auto& texel : texels) rgba.insert(rgba.end(), {texel[0], texel[1], texel[2], 255});
  scene::Texture texture = scene::textureFromPixels("test", width, height, std::move(rgba));
  texture.wrapU = texture.wrapV = wrap;
  return texture;
}

}  // namespace

TEST(Texture, DecodesAPngWithItsFirstRowAtTheTop) {
  auto texture = scene::decodeTexture(fileBytes(kAssets / "good" / "assets" / "tiles.png"), "tiles.png");
  ASSERT_TRUE(texture) << texture.error();
  ASSERT_EQ(texture->levels.front().width, 16);
  ASSERT_EQ(texture->levels.front().height, 16);
  EXPECT_EQ(texture->levels.size(), 5u) << "16, 8, 4, 2, 1";
  // tiles.png: 4×4-texel cells; the top-left one is (230, 220, 190), the one below it (170, 60, 50).
  const auto& rgba = texture->levels.front().rgba;
  EXPECT_EQ(rgba[0], 230);
  EXPECT_EQ(rgba[(4 * 16) * 4], 170);
}

TEST(Texture, GarbageIsRefusedByNameBeforeAnyLargeAllocation) {
  const auto refused = [](const std::string& bytes, const std::string& expected) {
    auto texture = scene::decodeTexture(bytes, "the image");
    ASSERT_FALSE(texture) << expected;
    EXPECT_TRUE(texture.error().starts_with("the image: ")) << texture.error();
    EXPECT_NE(texture.error().find(expected), std::string::npos) << texture.error();
  };
  refused("", "the image is empty");
  refused("plain words, no image", "not an image this build reads");
  refused("GIF89a and a header of nonsense", "(PNG, JPEG or Radiance .hdr)");
  refused("P5\n9 9\n255\n", "(PNG, JPEG or Radiance .hdr)");  // stb's PNM reader crashed on such headers
  refused("\x89PNG\r\n\x1a\n and a header of nonsense", "not an image this build reads");
  refused(fileBytes(kAssets / "bad" / "assets" / "not-an-image.png"), "not an image this build reads");
  refused(fileBytes(kAssets / "bad" / "assets" / "truncated.png"), "the image cannot be decoded");
  refused(fileBytes(kAssets / "bad" / "assets" / "huge.png"),
          "the image is 9000x16 texels; a texture side must be 1..8192");
}

// A Radiance file: the header, the resolution line and `scanlines` as written.
std::string radiance(int width, int height, const std::string& scanlines,
                     const std::string& header = "FORMAT=32-bit_rle_rgbe\n") {
  return "#?RADIANCE\n" + header + "\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n" + scanlines;
}

std::string bytesOf(std::initializer_list<int> values) {
  std::string bytes;
  for (int v : values) bytes += static_cast<char>(v);
  return bytes;
}

// RGBE (128, 64, 32, 129) is (128, 64, 32) × 2^(129 − 136) = (1, 0.5, 0.25) in linear light, sRGB (255, 188, 137);
// exponent 0 is black; (255, 255, 255, 140) is 16 × brighter than white, clamped to it.
TEST(Texture, DecodesRadianceImagesFlatAndRunLengthEncoded) {
  const std::string flat =
      radiance(2, 2, bytesOf({128, 64, 32, 129, 0, 0, 0, 0, 255, 255, 255, 140, 128, 64, 32, 129}));
  auto texture = scene::decodeTexture(flat, "flat.hdr");
  ASSERT_TRUE(texture) << texture.error();
  const auto& texels = texture->levels.front().rgba;
  ASSERT_EQ(texels.size(), 16u);
  EXPECT_EQ(std::vector<std::uint8_t>(texels.begin(), texels.begin() + 12),
            (std::vector<std::uint8_t>{255, 188, 137, 255, 0, 0, 0, 255, 255, 255, 255, 255}));
  // 8 texels a row, run-length encoded: each channel one run of 8 (128 + 8), except blue as 8 literals.
  std::string row = bytesOf({2, 2, 0, 8, 136, 128, 136, 64, 8, 32, 32, 32, 32, 32, 32, 32, 32, 136, 129});
  auto encoded = scene::decodeTexture(radiance(8, 2, row + row), "encoded.hdr");
  ASSERT_TRUE(encoded) << encoded.error();
  for (std::size_t texel = 0; texel < 16; ++texel) EXPECT_EQ(encoded->levels.front().rgba[4 * texel + 1], 188) << texel;
  EXPECT_EQ(scene::decodeTexture("#?RGBE\n\n-Y 1 +X 1\n" + bytesOf({128, 64, 32, 129}), "rgbe.hdr")->levels[0].rgba[2],
            137);
}

TEST(Texture, BrokenRadianceImagesAreRefusedByWhatIsWrong) {
  const auto refused = [](const std::string& bytes, const std::string& expected) {
    auto texture = scene::decodeTexture(bytes, "sky.hdr");
    ASSERT_FALSE(texture) << expected;
    EXPECT_NE(texture.error().find(expected), std::string::npos) << texture.error();
  };
  const std::string texel = bytesOf({128, 64, 32, 129});
  refused("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", "the Radiance header does not end");
  refused(radiance(1, 1, texel, "FORMAT=32-bit_rle_xyze\n"), "FORMAT=32-bit_rle_xyze is not read");
  refused("#?RADIANCE\n\n+Y 1 +X 1\n" + texel, "must read \"-Y <height> +X <width>\"");
  refused(radiance(9000, 1, ""), "the image is 9000x1 texels; a texture side must be 1..8192");
  refused(radiance(8192, 8192, std::string(4096, '\x01')), "4096 bytes cannot hold 8192 scanlines");
  refused(radiance(2, 1, texel), "4 bytes cannot hold 1 scanlines of 2 texels");
  refused(radiance(8, 1, std::string(20, '\x01')), "scanline 0 is truncated");  // flat: 32 bytes
  // A run of 9 in a row of 8, and a run that promises more bytes than follow.
  refused(radiance(8, 1, bytesOf({2, 2, 0, 8, 137, 1}) + std::string(32, '\x01')),
          "a run past the end of its scanline");
  refused(radiance(8, 1, bytesOf({2, 2, 0, 8, 8, 1, 2})) + std::string(21, '\x01'), "scanline 0 is truncated");
}

TEST(Texture, MipLevelsAverageInLinearLight) {
  // Black and white side by side: their average is half the light, sRGB 188, not the bytes' mean 128.
  const scene::Texture texture = textureOf(2, 1, {{0, 0, 0}, {255, 255, 255}});
  ASSERT_EQ(texture.levels.size(), 2u);
  EXPECT_EQ(texture.levels[1].width, 1);
  EXPECT_EQ(texture.levels[1].rgba[0], 188);
  // An odd side folds its last texel into the one before: 3×1 → one texel of all three.
  const scene::Texture odd = textureOf(3, 1, {{0, 0, 0}, {0, 0, 0}, {255, 255, 255}});
  ASSERT_EQ(odd.levels.size(), 2u);
  EXPECT_NEAR(math::srgbByteToLinear(odd.levels[1].rgba[0]), 1.0f / 3.0f, 0.005f);
  EXPECT_EQ(odd.texelCount(), 4u);
}

TEST(TextureSampler, FollowsGlFilteringAndWrapping) {
  const std::vector<std::array<std::uint8_t, 3>> texels = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  const scene::Texture repeat = textureOf(2, 2, texels);
  const auto linear = [](std::uint8_t byte) { return math::srgbByteToLinear(byte); };
  // Texel centres are exact; v = 0.25 is the first row (the image's top).
  EXPECT_FLOAT_EQ(reference::sampleTexture(repeat, {0.25f, 0.25f}, 0.0f).x, 1.0f);
  EXPECT_FLOAT_EQ(reference::sampleTexture(repeat, {0.75f, 0.25f}, 0.0f).y, 1.0f);
  EXPECT_FLOAT_EQ(reference::sampleTexture(repeat, {0.25f, 0.75f}, 0.0f).z, 1.0f);
  // Half way between two texels, bilinear: the mean of their linear values.
  EXPECT_FLOAT_EQ(reference::sampleTexture(repeat, {0.5f, 0.25f}, 0.0f).x, 0.5f);
  // Repeat: u = 1.25 is u = 0.25; clamp: the edge texel; mirrored repeat: u = 1.25 mirrors to 0.75.
  EXPECT_FLOAT_EQ(reference::sampleTexture(repeat, {1.25f, 0.25f}, 0.0f).x, 1.0f);
  EXPECT_FLOAT_EQ(
      reference::sampleTexture(textureOf(2, 2, texels, scene::TextureWrap::ClampToEdge), {1.25f, 0.25f}, 0.0f).y, 1.0f);
  EXPECT_FLOAT_EQ(
      reference::sampleTexture(textureOf(2, 2, texels, scene::TextureWrap::MirroredRepeat), {1.25f, 0.25f}, 0.0f).y,
      1.0f);
  EXPECT_FLOAT_EQ(
      reference::sampleTexture(textureOf(2, 2, texels, scene::TextureWrap::MirroredRepeat), {-0.25f, 0.25f}, 0.0f).x,
      1.0f);
  // A footprint of the whole texture reads the 1×1 level, the linear mean of all four.
  const glm::vec4 mean = reference::sampleTexture(repeat, {0.3f, 0.7f}, 1.0f);
  EXPECT_NEAR(mean.x, linear(repeat.levels[1].rgba[0]), 1e-6f);
  EXPECT_NEAR(mean.x, 0.5f, 0.005f);
  // Half way in levels (ρ = √2 texels): half of each.
  const glm::vec4 between = reference::sampleTexture(repeat, {0.25f, 0.25f}, std::sqrt(2.0f) / 2.0f);
  EXPECT_NEAR(between.x, 0.5f * 1.0f + 0.5f * linear(repeat.levels[1].rgba[0]), 1e-5f);
}

TEST(TextureSampler, FootprintGrowsWithDistanceAndObliquity) {
  EXPECT_FLOAT_EQ(reference::pixelFootprint(10.0f, 1.0f, 0.001f, 1.0f), 0.01f);
  EXPECT_FLOAT_EQ(reference::pixelFootprint(10.0f, 1.0f, 0.001f, -0.5f), 0.02f);
  EXPECT_FLOAT_EQ(reference::pixelFootprint(10.0f, 0.5f, 0.001f, 1.0f), 0.005f)
      << "an eye ray off the axis is shallower";
  EXPECT_FLOAT_EQ(reference::pixelFootprint(10.0f, 1.0f, 0.001f, 0.0f), 1.0f) << "grazing is capped at 1/100";
}

TEST(SamplePattern, CentredDistinctPointsInsideThePixel) {
  for (int samples : {1, 2, 4, 8, 16}) {
    ASSERT_FALSE(math::sampleCountProblem(samples).has_value()) << samples;
    const auto points = math::samplePattern(samples);
    ASSERT_EQ(points.size(), static_cast<std::size_t>(samples));
    glm::vec2 sum(0.0f);
    std::set<std::pair<float, float>> distinct;
    for (const glm::vec2& p : points) {
      EXPECT_LE(std::abs(p.x), 0.5f);
      EXPECT_LE(std::abs(p.y), 0.5f);
      sum += p;
      distinct.insert({p.x, p.y});
    }
    EXPECT_EQ(distinct.size(), points.size()) << samples;
    EXPECT_LE(glm::length(sum / static_cast<float>(samples)), 1.0f / 16.0f) << "about centred: " << samples;
  }
  for (int samples : {0, 3, 5, 32, -4}) EXPECT_TRUE(math::sampleCountProblem(samples).has_value()) << samples;
}
