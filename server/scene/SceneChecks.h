#pragma once
#include <optional>
#include <string>

#include "scene/Scene.h"

namespace specula::scene {

// The invariants every Scene must hold before it reaches a renderer, whatever built it
// (file loader, built-in generator, importer): indices in range, finite numbers, unit axes,
// well-formed animations and mirrors. Returns a message naming the first broken one, or nullopt.
std::optional<std::string> sceneProblem(const Scene& scene);

// Upper bounds that keep a hostile or mistaken asset from exhausting memory or GPU buffers.
inline constexpr std::size_t kMaxVerticesPerScene = 8u << 20;
inline constexpr std::size_t kMaxTrianglesPerScene = 8u << 20;

}  // namespace specula::scene
