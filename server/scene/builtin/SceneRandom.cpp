#include "scene/builtin/SceneRandom.h"

namespace specula::scene::builtin {

float SceneRandom::uniform(float lo, float hi) {
  // The top 24 bits fill a float mantissa exactly, so the result never rounds up to 1.
  const float unit = static_cast<float>(engine_() >> 8) / 16777216.0f;
  return lo + (hi - lo) * unit;
}

std::uint32_t SceneRandom::index(std::uint32_t count) {
  return static_cast<std::uint32_t>((static_cast<std::uint64_t>(engine_()) * count) >> 32);
}

}  // namespace specula::scene::builtin
