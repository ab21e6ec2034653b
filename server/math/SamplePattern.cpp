#include "math/SamplePattern.h"

#include <array>
#include <cassert>

namespace specula::math {

namespace {

// In sixteenths of a pixel, as the patterns are published.
template <std::size_t N>
constexpr std::array<glm::vec2, N> sixteenths(const std::array<glm::ivec2, N>& points) {
  std::array<glm::vec2, N> offsets{};
  for (std::size_t i = 0; i < N; ++i) offsets[i] = glm::vec2(points[i]) / 16.0f;
  return offsets;
}

const std::array<glm::vec2, 1> kOne{glm::vec2(0.0f)};
const auto kTwo = sixteenths<2>({{{4, 4}, {-4, -4}}});
const auto kFour = sixteenths<4>({{{-2, -6}, {6, -2}, {-6, 2}, {2, 6}}});
const auto kEight = sixteenths<8>({{{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}}});
const auto kSixteen = sixteenths<16>({{{1, 1},
                                       {-1, -3},
                                       {-3, 2},
                                       {4, -1},
                                       {-5, -2},
                                       {2, 5},
                                       {5, 3},
                                       {3, -5},
                                       {-2, 6},
                                       {0, -7},
                                       {-4, -6},
                                       {-6, 4},
                                       {-8, 0},
                                       {7, -4},
                                       {6, 7},
                                       {-7, -8}}});

}  // namespace

std::span<const glm::vec2> samplePattern(int samples) {
  switch (samples) {
    case 1: return kOne;
    case 2: return kTwo;
    case 4: return kFour;
    case 8: return kEight;
    case 16: return kSixteen;
    default: break;
  }
  assert(false && "sampleCountProblem(samples) must be nullopt");
  return kOne;
}

std::optional<std::string> sampleCountProblem(int samples) {
  if (samples == 1 || samples == 2 || samples == 4 || samples == 8 || samples == 16) return std::nullopt;
  return "samples per pixel must be 1, 2, 4, 8 or 16, got " + std::to_string(samples);
}

}  // namespace specula::math
