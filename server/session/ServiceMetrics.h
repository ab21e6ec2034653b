#pragma once
// The service's counters and histograms, served at GET /metrics in Prometheus text format.
#include <atomic>
#include <cstdint>
#include <string>

#include "net/Histogram.h"

namespace specula::session {

struct ServiceMetrics {
  std::atomic<std::int64_t> sessions{0};
  std::atomic<std::uint64_t> sessionsOpened{0}, sessionsRefused{0}, sessionsResumed{0}, resumesRefused{0};
  std::atomic<std::uint64_t> framesSent{0}, framesSkipped{0}, frameBytesSent{0};
  std::atomic<std::uint64_t> protocolErrors{0}, renderFailures{0}, writeTimeouts{0}, accuracyFailures{0};
  net::Histogram renderMs{{2, 5, 10, 20, 35, 50, 75, 100, 150, 250, 500, 1000, 2500}};
  net::Histogram encodeMs{{0.5, 1, 2, 5, 10, 20, 50, 100}};
  net::Histogram latencyMs{{5, 10, 20, 35, 50, 75, 100, 150, 250, 500, 1000, 2500}};  // input arrival → frame queued
  net::Histogram frameBytes{{8e3, 16e3, 32e3, 64e3, 128e3, 256e3, 512e3, 1e6}};
  // The live accuracy estimate of each frame sampled: its mirror mismatch (percent) and its CPU time.
  net::Histogram accuracyMismatch{{0.1, 0.25, 0.5, 1, 2, 5, 10, 25, 50, 100}};
  net::Histogram accuracyMs{{1, 2, 5, 10, 20, 50, 100, 250}};

  std::string prometheusText() const;
};

}  // namespace specula::session
