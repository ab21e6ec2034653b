#include "JpegDecoder.h"

namespace specula::view {

bool JpegDecoder::decode(std::string_view jpeg, RgbaImage& image) {
  int width = 0, height = 0, subsampling = 0, colourspace = 0;
  const auto* bytes = reinterpret_cast<const unsigned char*>(jpeg.data());
  const auto length = static_cast<unsigned long>(jpeg.size());
  if (tjDecompressHeader3(handle_, bytes, length, &width, &height, &subsampling, &colourspace) != 0) return false;
  image.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  if (tjDecompress2(handle_, bytes, length, image.pixels.data(), width, 0, height, TJPF_RGBA, 0) != 0) return false;
  image.width = width;
  image.height = height;
  return true;
}

}  // namespace specula::view
