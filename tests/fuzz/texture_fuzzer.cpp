// Texture files (PNG, JPEG, Radiance .hdr and whatever else the decoders read) as scenes and glTF images decode them.
#include <stb/stb_image.h>
#include <turbojpeg.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "scene/Texture.h"

namespace {

// The size a PNG's or JPEG's header claims, read as decodeTexture reads it; false when there is none.
bool headerSize(const std::uint8_t* data, std::size_t size, int& width, int& height) {
  if (size > 1u << 30) return false;
  int channels = 0, subsampling = 0, colourSpace = 0;
  if (size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff) {
    const std::unique_ptr<void, int (*)(tjhandle)> decoder(tjInitDecompress(), tjDestroy);
    return decoder && tjDecompressHeader3(decoder.get(), data, static_cast<unsigned long>(size), &width, &height,
                                          &subsampling, &colourSpace) == 0;
  }
  return stbi_info_from_memory(data, static_cast<int>(size), &width, &height, &channels) != 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Images over a megapixel that decodeTexture would accept run the same code as small ones, only slower
  // (a garbage JPEG of 8192x8192 decodes in full and builds its mip chain): skipped, as libjpeg-turbo's own
  // fuzzers do, so the fuzzer stays at thousands of inputs a second. Sides over the limit still go in.
  int width = 0, height = 0;
  if (headerSize(data, size, width, height) && width <= specula::scene::kMaxTextureSide &&
      height <= specula::scene::kMaxTextureSide && static_cast<long>(width) * height > (1L << 20))
    return 0;
  (void)specula::scene::decodeTexture(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.png");
  return 0;
}
