#pragma once
// The planner's cost rates on the device it runs on: predictPartCost() gives milliseconds on the
// llvmpipe it was fitted to, and each method's rate scales them to what frames rendered here
// measure. Plain data and arithmetic, no GL: the renderer feeds it the measured frames.
#include <optional>

#include "passes/FramePlan.h"

namespace specula::passes {

class MeasuredCosts {
 public:
  // Frame 1 (after the cold first frame, whose time is shader compilation) and then every
  // kMeasureEvery frames are timed pass by pass. On frames 2 and 3 and every kExploreEvery frames
  // every part takes the method measured longest ago (never, at first), so each rate stays
  // measured whichever the plan prefers; frame 2 is not measured, since a method's first frame
  // compiles its shaders (llvmpipe compiles a program on its first draw or dispatch).
  static constexpr int kMeasureEvery = 4, kExploreEvery = 32;
  // Each measurement after a method's first moves its rate this share of the way to what it measured.
  static constexpr double kLearningRate = 0.5;

  const CostRates& rates() const { return rates_; }

  // What the next frame is for: whether to time it pass by pass, and the method every part takes
  // to measure it (an exploration), if any. Advances the frame count.
  struct FrameRole {
    bool measure = false;
    std::optional<PartMethod> explore;
  };
  FrameRole nextFrame();

  // A measured frame: `predicted` is what predictPartCost() said (unscaled, summed over the parts
  // that used each method), `measured` what those parts' passes took. A method with no prediction
  // keeps its rate.
  void observe(const PartCost& predicted, const PartCost& measured);

 private:
  CostRates rates_;
  bool searchLearnt_ = false, rayCastLearnt_ = false;   // measured at least once
  int searchMeasuredAt_ = -1, rayCastMeasuredAt_ = -1;  // the frame of each method's last measurement
  int frame_ = 0;
};

}  // namespace specula::passes
