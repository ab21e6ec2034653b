#pragma once
// The stream's JPEG frames decoded into pixels for the window (TurboJPEG).
#include <turbojpeg.h>

#include <string_view>
#include <vector>

namespace specula::view {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;  // row 0 at the top
};

class JpegDecoder {
 public:
  JpegDecoder() : handle_(tjInitDecompress()) {}
  ~JpegDecoder() { tjDestroy(handle_); }
  JpegDecoder(const JpegDecoder&) = delete;
  JpegDecoder& operator=(const JpegDecoder&) = delete;

  // Decodes `jpeg` into `image`, reusing its buffer frame after frame; false if the bytes are no JPEG.
  bool decode(std::string_view jpeg, RgbaImage& image);

 private:
  tjhandle handle_;
};

}  // namespace specula::view
