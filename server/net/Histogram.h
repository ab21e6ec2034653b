#pragma once
// A thread-safe histogram with fixed bucket bounds, written in Prometheus text format.
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace specula::net {

class Histogram {
 public:
  explicit Histogram(std::vector<double> upperBounds);  // ascending; +Inf is implied

  void observe(double value);
  // `# HELP`, `# TYPE` and the cumulative `_bucket`, `_sum` and `_count` lines.
  void appendPrometheus(std::string& out, const std::string& name, const std::string& help) const;

 private:
  mutable std::mutex mutex_;
  std::vector<double> bounds_;
  std::vector<std::uint64_t> counts_;  // per bucket, not cumulative; last is +Inf
  double sum_ = 0.0;
  std::uint64_t count_ = 0;
};

// One `# HELP`/`# TYPE` block with a single sample (counter or gauge).
void appendPrometheusSample(std::string& out, const std::string& name, const std::string& type, const std::string& help,
                            double value);

}  // namespace specula::net
