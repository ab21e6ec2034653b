#pragma once
#include <string>

namespace specula::passes {

enum class ReflectionMethod {
  None,    // mirrors drawn with their own colour only
  Search,  // virtual objects from the screen-space reflection-point search (Estalella et al. 2006)
};

// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4), so virtual edges curve.
enum class TessellationMode {
  None,       // virtual triangles straight between their corners' reflections
  Paper,      // Szabo's loop: a triangle whose worst edge exceeds the threshold splits 1→4
  CrackFree,  // each edge decided alone and split triangles follow conforming patterns: no T-junctions
};

enum class TessellationMetric {
  Angle,   // Szabo's edge error 1 − (N_mid·b + 1)/2, from 0 to 1
  Pixels,  // where the rasterizer puts the edge midpoint against where its true reflection projects
};

struct TessellationSettings {
  TessellationMode mode = TessellationMode::CrackFree;
  TessellationMetric metric = TessellationMetric::Pixels;
  float threshold = 1.0f;  // an edge splits when its error is at least this (0: always; Angle 1: never)
  int maxLevel = 4;        // splits per original triangle at most: at most 4^maxLevel triangles each
};

// "crack-free pixels >= 1 level 4", or "none": how reports name a setting.
std::string describeTessellation(const TessellationSettings& settings);

struct ReflectionSettings {
  ReflectionMethod method = ReflectionMethod::Search;
  // Extra G-buffer border on each side, as a share of the frame size, so reflection points of a
  // mirror just off-screen still have texels.
  float gbufferMargin = 0.1f;
  // Start each vertex's search at last frame's texel; off forces cold starts (benchmarks, jumps).
  bool coherence = true;
  int maxWalkSteps = 64;  // bound on 3×3 windows per climb
  TessellationSettings tessellation;
};

}  // namespace specula::passes
