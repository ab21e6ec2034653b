#pragma once
// TurboJPEG compression of RGBA frames. One encoder per thread: the handle is not shareable.
#include <cstdint>
#include <vector>

#include "base/Result.h"
#include "encode/ImageView.h"

namespace specula::encode {

class JpegEncoder {
 public:
  JpegEncoder();
  ~JpegEncoder();
  JpegEncoder(const JpegEncoder&) = delete;
  JpegEncoder& operator=(const JpegEncoder&) = delete;

  // quality in [1, 100]; 4:2:0 chroma subsampling.
  Result<std::vector<std::uint8_t>> encode(const ImageView& image, int quality);

 private:
  void* handle_;
};

}  // namespace specula::encode
