#pragma once
#include <cstdint>
#include <vector>

#include "base/Result.h"
#include "encode/ImageView.h"

namespace specula::encode {

// Lossless RGBA PNG, for reference images and tests. Thread-safe (no shared state).
Result<std::vector<std::uint8_t>> encodePng(const ImageView& image);

}  // namespace specula::encode
