#pragma once
// Nearest-rank percentiles, as the bench and the load clients report them (errors, latencies).
#include <algorithm>
#include <cmath>
#include <vector>

namespace specula {

// The `fraction`-quantile (0 ≤ fraction ≤ 1; 0.99 for p99) of unsorted `values` by the nearest-rank
// definition: the smallest value with at least that share of all at or below it; 0 when there are none.
inline double nearestRankPercentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(fraction * static_cast<double>(values.size()));
  return values[static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size()))) - 1];
}

}  // namespace specula
