#pragma once
// Radiance RGBE images (.hdr, "#?RADIANCE" or "#?RGBE"), the common format of environment maps: read by
// this decoder alone, every length checked against the bytes there are (stb_image's decoders have crashed
// on hostile input, so none of its others is used).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"

namespace specula::scene {

struct RadianceImage {
  int width = 0, height = 0;
  // sRGB-encoded colour of the radiance clamped to [0, 1] (frames are 8-bit: brighter light would clip
  // there anyway), alpha 255, row 0 at the top; EXPOSURE lines are not applied.
  std::vector<std::uint8_t> rgba;
};

// The image in `bytes`: 32-bit_rle_rgbe, in the standard orientation (-Y h +X w), scanlines flat or
// run-length encoded. Fails, naming `name`, on any other format or orientation, a side outside
// 1..maxSide or more texels than the bytes left could hold (both checked before decoding), or data that
// is truncated or overruns a scanline.
Result<RadianceImage> decodeRadiance(std::string_view bytes, const std::string& name, int maxSide);

}  // namespace specula::scene
