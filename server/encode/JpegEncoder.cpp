#include "encode/JpegEncoder.h"

#include <turbojpeg.h>

#include <string>

namespace specula::encode {

JpegEncoder::JpegEncoder() : handle_(tjInitCompress()) {}
JpegEncoder::~JpegEncoder() {
  if (handle_) tjDestroy(handle_);
}

Result<std::vector<std::uint8_t>> JpegEncoder::encode(const ImageView& image, int quality) {
  if (!handle_) return Error{"TurboJPEG could not initialise a compressor"};
  if (!image.rgba || image.width <= 0 || image.height <= 0) return Error{"JPEG encoder: empty image"};
  if (quality < 1 || quality > 100) return Error{"JPEG quality " + std::to_string(quality) + " is outside [1, 100]"};
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  const int status = tjCompress2(handle_, image.rgba, image.width, image.width * 4, image.height, TJPF_RGBA, &buffer,
                                 &size, TJSAMP_420, quality, TJFLAG_FASTDCT);
  if (status != 0) {
    std::string message = std::string("TurboJPEG: ") + tjGetErrorStr2(handle_);
    tjFree(buffer);
    return Error{message};
  }
  std::vector<std::uint8_t> bytes(buffer, buffer + size);
  tjFree(buffer);
  return bytes;
}

}  // namespace specula::encode
