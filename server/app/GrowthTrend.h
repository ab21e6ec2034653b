#pragma once
// Whether a resource sampled through a long run grows: a least-squares line through the samples after
// a warm-up, judged by what it adds over the measured time and by whether its slope stands out from the
// samples' scatter. Pure arithmetic: `specula bench soak` feeds it samples, the unit tests made-up series.
#include <cstddef>
#include <span>

namespace specula::app {

struct GrowthLimit {
  double absolute = 0.0;       // growth over the measured time always tolerated, in the series' unit
  double relative = 0.0;       // plus this share of the fitted level where measuring starts
  double minTStatistic = 3.0;  // the slope counts only this many standard errors above zero
};

struct GrowthTrend {
  std::size_t samples = 0;  // at or after the warm-up
  double slopePerSecond = 0.0;
  double startLevel = 0.0, endLevel = 0.0;  // the fitted line at the first and the last measured sample
  double growth = 0.0;                      // endLevel - startLevel: the slope over the measured time
  double tolerance = 0.0;                   // absolute + relative × startLevel
  double tStatistic = 0.0;                  // slope / its standard error; infinite for an exact rising line
  bool grows = false;                       // growth > tolerance and tStatistic >= the limit's
};

// Fits values[i] against seconds[i] over the samples at or after `warmupSeconds`; fewer than 3 there
// cannot show a trend and never grow.
GrowthTrend growthTrend(std::span<const double> seconds, std::span<const double> values, double warmupSeconds,
                        const GrowthLimit& limit);

}  // namespace specula::app
