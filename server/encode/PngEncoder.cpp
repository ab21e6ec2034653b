#include "encode/PngEncoder.h"

#include <stb_image_write.h>

namespace specula::encode {

Result<std::vector<std::uint8_t>> encodePng(const ImageView& image) {
  if (!image.rgba || image.width <= 0 || image.height <= 0) return Error{"PNG encoder: empty image"};
  std::vector<std::uint8_t> bytes;
  const int ok = stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* begin = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), begin, begin + size);
      },
      &bytes, image.width, image.height, 4, image.rgba, image.width * 4);
  if (!ok) return Error{"PNG encoder failed (out of memory?)"};
  return bytes;
}

}  // namespace specula::encode
