#pragma once
// CPU view of one search result: the std430 twin of shaders/common/reflected-vertex.glsl.
#include <cstdint>
#include <glm/glm.hpp>

namespace specula::passes {

struct ReflectedVertex {
  static constexpr std::int32_t kHidden = 1, kUnsolved = 2, kColdStart = 4, kEnlarged = 8, kInNoCone = 16;

  glm::vec4 virtualPosition;   // world; w = 1 when solved
  glm::vec4 reflectionPoint;   // world R
  glm::vec4 reflectionNormal;  // unit N at R
  glm::ivec4 state;            // xy: level-0 texel, z: steps, w: flags
};
static_assert(sizeof(ReflectedVertex) == 64, "must match the std430 layout in reflected-vertex.glsl");

// Per-frame totals written by the search (std430 twin of SearchStatistics in search.comp).
struct SearchStatistics {
  std::uint32_t searched = 0, hidden = 0, unsolved = 0, coldStarts = 0;
  std::uint32_t totalSteps = 0, maxSteps = 0, warmSteps = 0, coldSteps = 0;
  // The ray-hierarchy search: vertices in no cone until Szabo's enlargement, and in none even then.
  std::uint32_t enlarged = 0, inNoCone = 0;
};

}  // namespace specula::passes
