// Texture files (PNG, JPEG and whatever else stb_image reads) as scenes and glTF images decode them.
#include <stb/stb_image.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/Texture.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Images over a megapixel that decodeTexture would accept run the same code as small ones, only slower
  // (a garbage JPEG of 8192x8192 decodes in full and builds its mip chain): skipped, as libjpeg-turbo's own
  // fuzzers do, so the fuzzer stays at thousands of inputs a second. Sides over the limit still go in.
  int width = 0, height = 0, channels = 0;
  if (size <= 1u << 30 && stbi_info_from_memory(data, static_cast<int>(size), &width, &height, &channels) &&
      width <= specula::scene::kMaxTextureSide && height <= specula::scene::kMaxTextureSide &&
      static_cast<long>(width) * height > (1L << 20))
    return 0;
  (void)specula::scene::decodeTexture(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.png");
  return 0;
}
