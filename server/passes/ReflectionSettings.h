#pragma once

namespace specula::passes {

enum class ReflectionMethod {
  None,    // mirrors drawn with their own colour only
  Search,  // virtual objects from the screen-space reflection-point search (Estalella et al. 2006)
};

struct ReflectionSettings {
  ReflectionMethod method = ReflectionMethod::Search;
  // Extra G-buffer border on each side, as a share of the frame size, so reflection points of a
  // mirror just off-screen still have texels.
  float gbufferMargin = 0.1f;
  // Start each vertex's search at last frame's texel; off forces cold starts (benchmarks, jumps).
  bool coherence = true;
  int maxWalkSteps = 64;  // bound on 3×3 windows per climb
};

}  // namespace specula::passes
