#include "passes/MeasuredCosts.h"

#include <algorithm>
#include <cmath>

namespace specula::passes {

namespace {
// A rate is kept within these bounds of the fitted model: a frame that took nothing (work skipped)
// or an outlier (a page fault, a busy neighbour) moves it only so far.
constexpr double kMinRate = 1e-3, kMaxRate = 1e3;

// The first measurement of a method replaces the fit's guess; later ones move the rate part way.
void learn(double& rate, bool& learnt, int& measuredAt, int frame, double predicted, double measured) {
  if (!(predicted > 0.0) || !(measured >= 0.0) || !std::isfinite(measured)) return;
  const double observed = std::clamp(measured / predicted, kMinRate, kMaxRate);
  rate += (learnt ? MeasuredCosts::kLearningRate : 1.0) * (observed - rate);
  learnt = true;
  measuredAt = frame;
}
}  // namespace

MeasuredCosts::FrameRole MeasuredCosts::nextFrame() {
  const int frame = frame_++;
  FrameRole role;
  if (frame == 2 || frame == 3 || (frame > 3 && frame % kExploreEvery == 0))
    role.explore = searchMeasuredAt_ <= rayCastMeasuredAt_ ? PartMethod::VirtualObjects : PartMethod::RayCast;
  role.measure = frame == 1 || frame == 3 || (frame > 3 && (frame % kMeasureEvery == 0 || role.explore));
  return role;
}

void MeasuredCosts::observe(const PartCost& predicted, const PartCost& measured) {
  const int frame = frame_ - 1;  // the frame nextFrame() last handed out
  learn(rates_.search, searchLearnt_, searchMeasuredAt_, frame, predicted.search, measured.search);
  learn(rates_.rayCast, rayCastLearnt_, rayCastMeasuredAt_, frame, predicted.rayCast, measured.rayCast);
}

}  // namespace specula::passes
