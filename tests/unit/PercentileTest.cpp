// The one nearest-rank percentile the bench and the load clients report: p as a fraction of the values.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "base/Percentile.h"

using namespace specula;

TEST(Percentile, NearestRankOfUnsortedValues) {
  EXPECT_EQ(nearestRankPercentile({}, 0.5), 0.0);
  EXPECT_EQ(nearestRankPercentile({5, 1, 3, 2, 4}, 0.5), 3.0);
  EXPECT_EQ(nearestRankPercentile({5, 1, 3, 2, 4}, 1.0), 5.0);
  EXPECT_EQ(nearestRankPercentile({5, 1, 3, 2, 4}, 0.0), 1.0);
  std::vector<double> hundred(100);
  std::iota(hundred.begin(), hundred.end(), 1.0);
  EXPECT_EQ(nearestRankPercentile(hundred, 0.99), 99.0);
  EXPECT_EQ(nearestRankPercentile(hundred, 0.1), 10.0);
}
