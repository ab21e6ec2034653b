#pragma once
// Bounds on lists and tessellation, so no file allocates without limit before the vertex budget applies.
#include <cstddef>
#include <cstdint>

namespace specula::scene::file {

inline constexpr std::size_t kMaxEntities = 10000;  // meshes, materials, objects, animations, each
inline constexpr std::size_t kMaxKeys = 100000;     // keyframes per path
inline constexpr std::size_t kMaxProfilePoints = 1024;
inline constexpr std::int64_t kMaxSegments = 1024;  // grid cells per side, slices, stacks, torus segments
inline constexpr std::size_t kMaxIncludes = 64;     // glTF files included, each read whole

}  // namespace specula::scene::file
