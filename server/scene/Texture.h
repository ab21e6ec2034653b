#pragma once
// Colour textures: decoded once at load (PNG through stb_image, JPEG through libjpeg-turbo, Radiance .hdr
// through scene/RadianceImage, clamped to [0, 1]), their mip chain built
// here in linear light, so the GPU (passes/GpuTextures uploads these very levels) and the reference's
// sampler (reference/TextureSampler) filter the same texels.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"

namespace specula::scene {

// Largest side and texel count a texture may have, and the texels of all textures of one scene
// (about 1 GiB of RGBA8 with mip chains): bounds what a file can make the server allocate.
inline constexpr int kMaxTextureSide = 8192;
inline constexpr std::size_t kMaxTexelsPerScene = std::size_t{192} << 20;

// How uv outside [0, 1] wraps (glTF sampler wrapS/wrapT; GL's names).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

struct TextureLevel {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // sRGB-encoded colour, linear alpha, row 0 at v = 0, tightly packed
};

struct Texture {
  std::string name;                  // the file or glTF image it came from, for messages
  std::vector<TextureLevel> levels;  // level 0 the image; each next half the last (rounded down, at least 1) to 1×1
  TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;

  std::size_t texelCount() const;  // all levels
};

// The image in `bytes` (PNG, JPEG or Radiance .hdr) as RGBA8, its mip chain built by averaging 2×2
// texels in linear light (an odd side folds its last row or column into the one before). Fails,
// naming `name` and the fix, on bytes that are no image of those formats, a truncated or corrupt
// image, or a side over kMaxTextureSide (checked from the header, before decoding).
Result<Texture> decodeTexture(std::string_view bytes, std::string name);

// Builds the mip chain of an RGBA8 image (sRGB colour) already in memory; `rgba` holds width·height texels.
Texture textureFromPixels(std::string name, int width, int height, std::vector<std::uint8_t> rgba);

}  // namespace specula::scene
