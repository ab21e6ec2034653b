#include "scene/Texture.h"

#include <stb/stb_image.h>
#include <turbojpeg.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "math/Color.h"
#include "scene/RadianceImage.h"

namespace specula::scene {

namespace {

std::uint8_t toByte(float unit) {
  return static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(unit, 0.0f, 1.0f)));
}

// The next level: each texel the average, in linear light, of the texels of `level` it covers (2 or 3 a side).
TextureLevel halve(const TextureLevel& level) {
  TextureLevel next;
  next.width = std::max(1, level.width / 2);
  next.height = std::max(1, level.height / 2);
  next.rgba.resize(static_cast<std::size_t>(next.width) * static_cast<std::size_t>(next.height) * 4);
  for (int y = 0; y < next.height; ++y) {
    const int y0 = y * level.height / next.height, y1 = (y + 1) * level.height / next.height;
    for (int x = 0; x < next.width; ++x) {
      const int x0 = x * level.width / next.width, x1 = (x + 1) * level.width / next.width;
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx) {
          const std::uint8_t* texel =
              &level.rgba[(static_cast<std::size_t>(sy) * static_cast<std::size_t>(level.width) +
                           static_cast<std::size_t>(sx)) *
                          4];
          for (int c = 0; c < 3; ++c) sum[c] += math::srgbByteToLinear(texel[c]);
          sum[3] += static_cast<float>(texel[3]) / 255.0f;
        }
      const float count = static_cast<float>((x1 - x0) * (y1 - y0));
      std::uint8_t* out = &next.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(next.width) +
                                      static_cast<std::size_t>(x)) *
                                     4];
      for (int c = 0; c < 3; ++c) out[c] = toByte(math::linearToSrgb(sum[c] / count));
      out[3] = toByte(sum[3] / count);
    }
  }
  return next;
}

struct DecodedImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// The header's size, checked before anything is allocated for the texels.
Status checkSide(const std::string& name, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxTextureSide || height > kMaxTextureSide)
    return Error{name + ": the image is " + std::to_string(width) + "x" + std::to_string(height) +
                 " texels; a texture side must be 1.." + std::to_string(kMaxTextureSide) + ", so scale it down"};
  return {};
}

Result<DecodedImage> decodePng(std::string_view bytes, const std::string& name) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
  DecodedImage image;
  int channels = 0;
  if (!stbi_info_from_memory(data, length, &image.width, &image.height, &channels))
    return Error{name + ": not an image this build reads (" + std::string(stbi_failure_reason()) +
                 "); use PNG or JPEG"};
  if (Status side = checkSide(name, image.width, image.height); !side) return Error{side.error()};
  int decodedWidth = 0, decodedHeight = 0;
  stbi_uc* pixels = stbi_load_from_memory(data, length, &decodedWidth, &decodedHeight, &channels, 4);
  if (!pixels)
    return Error{name + ": the image cannot be decoded (" + std::string(stbi_failure_reason()) +
                 "); is it truncated or corrupt?"};
  const std::unique_ptr<stbi_uc, void (*)(void*)> owned(pixels, stbi_image_free);
  if (decodedWidth != image.width || decodedHeight != image.height)
    return Error{name + ": the image's header and its data disagree on its size"};
  image.rgba.assign(pixels,
                    pixels + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
  return image;
}

// libjpeg-turbo, the decoder OSS-Fuzz keeps fuzzing: corrupt data is an error (not a warning decoded as
// grey), and a progressive file may not make it run thousands of scans.
Result<DecodedImage> decodeJpeg(std::string_view bytes, const std::string& name) {
  const std::unique_ptr<void, int (*)(tjhandle)> decoder(tjInitDecompress(), tjDestroy);
  if (!decoder) return Error{name + ": the JPEG decoder could not start: " + std::string(tjGetErrorStr2(nullptr))};
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto length = static_cast<unsigned long>(bytes.size());
  DecodedImage image;
  int subsampling = 0, colourSpace = 0;
  if (tjDecompressHeader3(decoder.get(), data, length, &image.width, &image.height, &subsampling, &colourSpace) != 0)
    return Error{name + ": not a JPEG this build reads (" + std::string(tjGetErrorStr2(decoder.get())) +
                 "); use PNG or JPEG"};
  if (Status side = checkSide(name, image.width, image.height); !side) return Error{side.error()};
  image.rgba.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
  if (tjDecompress2(decoder.get(), data, length, image.rgba.data(), image.width, 0, image.height, TJPF_RGBA,
                    TJFLAG_ACCURATEDCT | TJFLAG_STOPONWARNING | TJFLAG_LIMITSCANS) != 0)
    return Error{name + ": the image cannot be decoded (" + std::string(tjGetErrorStr2(decoder.get())) +
                 "); is it truncated or corrupt?"};
  return image;
}

}  // namespace

std::size_t Texture::texelCount() const {
  std::size_t count = 0;
  for (const TextureLevel& level : levels)
    count += static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height);
  return count;
}

Texture textureFromPixels(std::string name, int width, int height, std::vector<std::uint8_t> rgba) {
  Texture texture;
  texture.name = std::move(name);
  texture.levels.push_back({width, height, std::move(rgba)});
  while (texture.levels.back().width > 1 || texture.levels.back().height > 1)
    texture.levels.push_back(halve(texture.levels.back()));
  return texture;
}

Result<Texture> decodeTexture(std::string_view bytes, std::string name) {
  if (bytes.empty()) return Error{name + ": the image is empty"};
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return Error{name + ": the image file is too large to decode"};
  // The two formats glTF allows and Radiance's, each by a decoder that survives fuzzing: stb_image's other
  // decoders crash Debian's build on hostile PNM files, and its JPEG decoder asserts (aborts) on corrupt ones.
  if (bytes.starts_with("#?")) {
    Result<RadianceImage> radiance = decodeRadiance(bytes, name, kMaxTextureSide);
    if (!radiance) return Error{radiance.error()};
    return textureFromPixels(std::move(name), radiance->width, radiance->height, std::move(radiance->rgba));
  }
  const bool png = bytes.starts_with("\x89PNG\r\n\x1a\n"), jpeg = bytes.starts_with("\xff\xd8\xff");
  if (!png && !jpeg)
    return Error{name + ": not an image this build reads (PNG, JPEG or Radiance .hdr); convert it to one of them"};
  Result<DecodedImage> image = jpeg ? decodeJpeg(bytes, name) : decodePng(bytes, name);
  if (!image) return Error{image.error()};
  return textureFromPixels(std::move(name), image->width, image->height, std::move(image->rgba));
}

}  // namespace specula::scene
