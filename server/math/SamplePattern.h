#pragma once
// Where inside a pixel an anti-aliased frame samples: the standard multisample positions (the
// D3D/Vulkan patterns for 2, 4, 8 and 16 samples), shared by the rasterizer's jittered frames
// (render::Renderer) and the reference ray tracer, so both average the very same sample points.
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

namespace specula::math {

// Still frames (`specula render`, the bench's image comparison, serve's full-quality frame after
// input) take this many samples by default; interactive frames one.
inline constexpr int kStillFrameSamples = 4;

// The offsets of `samples` sample points from the pixel centre, in pixels, x to the right and y
// down (image rows); a single sample is the centre. Requires sampleCountProblem(samples) == nullopt.
std::span<const glm::vec2> samplePattern(int samples);

// What is wrong with `samples` as a sample count (1, 2, 4, 8 or 16), nullopt when nothing is.
std::optional<std::string> sampleCountProblem(int samples);

}  // namespace specula::math
