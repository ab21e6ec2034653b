#include "app/GrowthTrend.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace specula::app {

GrowthTrend growthTrend(std::span<const double> seconds, std::span<const double> values, double warmupSeconds,
                        const GrowthLimit& limit) {
  std::vector<double> t, v;
  for (std::size_t i = 0; i < std::min(seconds.size(), values.size()); ++i)
    if (seconds[i] >= warmupSeconds) {
      t.push_back(seconds[i]);
      v.push_back(values[i]);
    }
  GrowthTrend trend;
  trend.samples = t.size();
  if (t.size() < 3) return trend;
  const double n = static_cast<double>(t.size());
  double meanT = 0.0, meanV = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    meanT += t[i] / n;
    meanV += v[i] / n;
  }
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    sxx += (t[i] - meanT) * (t[i] - meanT);
    sxy += (t[i] - meanT) * (v[i] - meanV);
  }
  if (sxx <= 0.0) return trend;  // every sample at one instant: no slope to speak of
  trend.slopePerSecond = sxy / sxx;
  const auto fitted = [&](double at) { return meanV + trend.slopePerSecond * (at - meanT); };
  double residuals = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) residuals += (v[i] - fitted(t[i])) * (v[i] - fitted(t[i]));
  const double slopeError = std::sqrt(residuals / (n - 2.0) / sxx);
  if (slopeError > 0.0) trend.tStatistic = trend.slopePerSecond / slopeError;
  else if (trend.slopePerSecond != 0.0)
    trend.tStatistic = std::copysign(std::numeric_limits<double>::infinity(), trend.slopePerSecond);
  trend.startLevel = fitted(t.front());
  trend.endLevel = fitted(t.back());
  trend.growth = trend.endLevel - trend.startLevel;
  trend.tolerance = limit.absolute + limit.relative * std::max(0.0, trend.startLevel);
  trend.grows = trend.growth > trend.tolerance && trend.tStatistic >= limit.minTStatistic;
  return trend;
}

}  // namespace specula::app
