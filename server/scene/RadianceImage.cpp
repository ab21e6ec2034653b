#include "scene/RadianceImage.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>

#include "math/Color.h"

namespace specula::scene {

namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

// Reads "-Y <height> +X <width>" exactly.
bool parseResolution(std::string_view line, int& width, int& height) {
  const auto number = [&](std::string_view prefix, int& value) {
    if (!line.starts_with(prefix)) return false;
    line.remove_prefix(prefix.size());
    const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), value);
    if (error != std::errc{}) return false;
    line.remove_prefix(static_cast<std::size_t>(end - line.data()));
    return true;
  };
  return number("-Y ", height) && number(" +X ", width) && line.empty();
}

// One scanline of `width` RGBE texels from `bytes` at `at`: the new run-length encoding (2, 2, width, then
// each channel in runs) where it starts so, flat texels otherwise.
Status readScanline(std::string_view bytes, std::size_t& at, int width, std::uint8_t* rgbe, const std::string& where) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(bytes[i]); };
  const auto w = static_cast<std::size_t>(width);
  const bool encoded = width >= 8 && width < 0x8000 && bytes.size() - at >= 4 && byte(at) == 2 && byte(at + 1) == 2 &&
                       ((byte(at + 2) << 8) | byte(at + 3)) == width;
  if (!encoded) {
    if (bytes.size() - at < 4 * w) return Error{where + "is truncated"};
    for (std::size_t i = 0; i < 4 * w; ++i) rgbe[i] = byte(at + i);
    at += 4 * w;
    return {};
  }
  at += 4;
  for (std::size_t channel = 0; channel < 4; ++channel) {
    for (std::size_t x = 0; x < w;) {
      if (at >= bytes.size()) return Error{where + "is truncated"};
      const std::uint8_t count = byte(at++);
      const bool run = count > 128;
      const std::size_t length = run ? count - 128u : count;
      if (length == 0) return Error{where + "has an empty run"};
      if (length > w - x) return Error{where + "has a run past the end of its scanline"};
      if (bytes.size() - at < (run ? 1 : length)) return Error{where + "is truncated"};
      for (std::size_t i = 0; i < length; ++i, ++x) rgbe[4 * x + channel] = byte(run ? at : at + i);
      at += run ? 1 : length;
    }
  }
  return {};
}

}  // namespace

Result<RadianceImage> decodeRadiance(std::string_view bytes, const std::string& name, int maxSide) {
  if (!bytes.starts_with("#?RADIANCE\n") && !bytes.starts_with("#?RGBE\n"))
    return Error{name + ": not a Radiance image (it must start with #?RADIANCE or #?RGBE)"};
  // Header lines up to a blank one; then the resolution line.
  std::size_t at = 0;
  const auto nextLine = [&]() -> std::optional<std::string_view> {
    const std::size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos || end > kMaxHeaderBytes) return std::nullopt;
    const std::string_view line = bytes.substr(at, end - at);
    at = end + 1;
    return line;
  };
  for (;;) {
    const std::optional<std::string_view> line = nextLine();
    if (!line) return Error{name + ": the Radiance header does not end (no blank line in its first 64 KiB)"};
    if (line->empty()) break;
    if (line->starts_with("FORMAT=") && *line != "FORMAT=32-bit_rle_rgbe")
      return Error{name + ": " + std::string(*line) + " is not read; only FORMAT=32-bit_rle_rgbe (RGB) is"};
  }
  const std::optional<std::string_view> resolution = nextLine();
  RadianceImage image;
  if (!resolution || !parseResolution(*resolution, image.width, image.height))
    return Error{name + ": the resolution line must read \"-Y <height> +X <width>\" (the standard orientation)"};
  if (image.width < 1 || image.height < 1 || image.width > maxSide || image.height > maxSide)
    return Error{name + ": the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                 " texels; a texture side must be 1.." + std::to_string(maxSide) + ", so scale it down"};
  const auto width = static_cast<std::size_t>(image.width);
  // The fewest bytes a scanline takes (flat, or four channels in runs of at most 127), so a short file
  // cannot make the decoder allocate for a large image.
  const std::size_t fewestBytes = std::min(4 * width, 4 + 4 * 2 * ((width + 126) / 127));
  if ((bytes.size() - at) / fewestBytes < static_cast<std::size_t>(image.height))
    return Error{name + ": the image is truncated: " + std::to_string(bytes.size() - at) + " bytes cannot hold " +
                 std::to_string(image.height) + " scanlines of " + std::to_string(image.width) + " texels"};
  std::vector<std::uint8_t> rgbe(4 * width);
  image.rgba.resize(4 * width * static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) {
    const std::string where = name + ": scanline " + std::to_string(y) + " ";
    if (Status read = readScanline(bytes, at, image.width, rgbe.data(), where); !read) return Error{read.error()};
    for (std::size_t x = 0; x < width; ++x) {
      const std::uint8_t exponent = rgbe[4 * x + 3];
      const float scale = exponent == 0 ? 0.0f : std::ldexp(1.0f, static_cast<int>(exponent) - (128 + 8));
      std::uint8_t* texel = &image.rgba[4 * (static_cast<std::size_t>(y) * width + x)];
      for (std::size_t c = 0; c < 3; ++c) {
        const float radiance = std::clamp(scale * static_cast<float>(rgbe[4 * x + c]), 0.0f, 1.0f);
        texel[c] = static_cast<std::uint8_t>(std::lround(255.0f * math::linearToSrgb(radiance)));
      }
      texel[3] = 255;
    }
  }
  return image;
}

}  // namespace specula::scene
