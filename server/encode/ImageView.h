#pragma once
#include <cstdint>

namespace specula::encode {

// Borrowed RGBA8 pixels, tightly packed, row 0 at the top. Encoders depend on no other module.
struct ImageView {
  const std::uint8_t* rgba = nullptr;
  int width = 0;
  int height = 0;
};

}  // namespace specula::encode
