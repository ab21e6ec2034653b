// Texture files (PNG, JPEG and whatever else stb_image reads) as scenes and glTF images decode them.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/Texture.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)specula::scene::decodeTexture(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.png");
  return 0;
}
