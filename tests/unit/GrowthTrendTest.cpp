// The soak's growth detector on made-up series: noise passes, a slow leak fails, no clock involved.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "app/GrowthTrend.h"

namespace specula::app {
namespace {

// One sample every 5 s for 10 minutes: level + slope × t + a fixed pseudo-random wobble of ±noise.
struct Series {
  std::vector<double> seconds, values;
};
Series series(double level, double slopePerSecond, double noise) {
  Series s;
  std::uint32_t state = 12345;
  for (int i = 0; i <= 120; ++i) {
    state = state * 1664525u + 1013904223u;  // a linear congruential generator: the same wobble every run
    const double wobble = (static_cast<double>(state >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
    const double t = 5.0 * i;
    s.seconds.push_back(t);
    s.values.push_back(level + slopePerSecond * t + noise * wobble);
  }
  return s;
}

constexpr GrowthLimit kLimit{8.0, 0.02, 3.0};  // 8 units plus 2 % of the level

TEST(GrowthTrend, FlatNoisySeriesPasses) {
  const Series s = series(300.0, 0.0, 6.0);
  const GrowthTrend trend = growthTrend(s.seconds, s.values, 60.0, kLimit);
  EXPECT_EQ(trend.samples, 109u);
  EXPECT_LT(trend.growth, trend.tolerance);
  EXPECT_FALSE(trend.grows);
}

TEST(GrowthTrend, SlowlyGrowingSeriesFails) {
  // 3 units a minute: 27 over the measured 9 minutes, under the noise's ±6 at any one sample.
  const Series s = series(300.0, 0.05, 6.0);
  const GrowthTrend trend = growthTrend(s.seconds, s.values, 60.0, kLimit);
  EXPECT_NEAR(trend.slopePerSecond, 0.05, 0.01);
  EXPECT_NEAR(trend.growth, 27.0, 6.0);
  EXPECT_GT(trend.tStatistic, 3.0);
  EXPECT_TRUE(trend.grows);
}

TEST(GrowthTrend, GrowthUnderTheToleranceIsAccepted) {
  const Series s = series(300.0, 0.01, 0.0);  // 5.4 over 9 minutes, an exact line
  const GrowthTrend trend = growthTrend(s.seconds, s.values, 60.0, kLimit);
  EXPECT_GT(trend.tStatistic, 3.0);
  EXPECT_NEAR(trend.tolerance, 8.0 + 0.02 * 300.6, 0.1);
  EXPECT_FALSE(trend.grows);
}

TEST(GrowthTrend, ShrinkingSeriesPasses) {
  const Series s = series(300.0, -0.2, 6.0);
  EXPECT_FALSE(growthTrend(s.seconds, s.values, 60.0, kLimit).grows);
}

TEST(GrowthTrend, WarmUpIsLeftOut) {
  Series s = series(300.0, 0.0, 1.0);
  for (std::size_t i = 0; i < s.values.size(); ++i)
    if (s.seconds[i] < 60.0) s.values[i] = 100.0 + 3.0 * s.seconds[i];  // caches filling at the start
  EXPECT_FALSE(growthTrend(s.seconds, s.values, 60.0, kLimit).grows);
  EXPECT_TRUE(growthTrend(s.seconds, s.values, 0.0, kLimit).grows) << "without the warm-up the filling counts";
}

TEST(GrowthTrend, TooFewSamplesNeverGrow) {
  const std::vector<double> seconds = {0.0, 100.0}, values = {0.0, 1000.0};
  const GrowthTrend trend = growthTrend(seconds, values, 0.0, kLimit);
  EXPECT_EQ(trend.samples, 2u);
  EXPECT_FALSE(trend.grows);
}

}  // namespace
}  // namespace specula::app
