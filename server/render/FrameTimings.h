#pragma once
#include <string>
#include <vector>

namespace specula::render {

// Milliseconds spent in one stage of a frame, measured on the GPU timeline (GL timestamp queries).
struct StageTiming {
  std::string name;
  double milliseconds = 0.0;
};

struct FrameTimings {
  std::vector<StageTiming> stages;  // in execution order: passes, then "readback"
  double totalMilliseconds = 0.0;   // wall clock from the first GL call to pixels in memory
};

}  // namespace specula::render
