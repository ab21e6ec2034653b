#pragma once
// N concurrent sessions against a server, each orbiting its own camera path and sending camera
// updates at a fixed input rate, for a bounded time. Measures what users feel: frames per second,
// input-to-frame latency (client send → frame reflecting it received), bytes, server timings.
// Shared by `specula-load` and `specula bench serve`.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ResumingClient.h"

namespace specula::client {

struct LoadOptions {
  ServerAddress address;
  protocol::Encoding encoding = protocol::Encoding::Proto;
  int sessions = 1;
  int width = 640, height = 360;
  std::chrono::milliseconds duration{5000};  // measured time, after the warm-up
  std::chrono::milliseconds warmup{1000};    // first frames (sizes, caches) are not counted
  double inputHz = 60.0;                     // camera updates per second per session
  double orbitDegreesPerSecond = 30.0;
  ReconnectPolicy reconnect;  // a lost session reconnects and resumes (ResumingClient)
  // When set, session N's policy instead (the soak's stopping readers connect through a thin pipe).
  std::function<ReconnectPolicy(int session)> sessionReconnect;
  // Called about once a second from the calling thread with the seconds done and frames so far.
  std::function<void(double seconds, std::uint64_t frames)> progress;
  // Called by each session before each read, with the seconds since the run began (warm-up included):
  // may send, pause or drop the connection, as `specula bench soak`'s clients do. An error ends the session.
  std::function<Status(int session, double seconds, ResumingClient& client)> script;
};

struct SessionLoad {
  std::uint64_t frames = 0, bytes = 0, skippedFrames = 0;
  double fps = 0.0;
  std::vector<double> latencyMs;  // one per measured frame
  double renderMsMean = 0.0, encodeMsMean = 0.0, serverMsMean = 0.0;
  int reconnects = 0;         // connections lost and won back
  int resumesRefused = 0;     // of those, the ones the server could not resume
  int resumed = 0;            // welcomes that brought the session back from its resume token
  double longestGapMs = 0.0;  // between two frames while measuring: what a lost connection cost
  // The live accuracy estimates received while measuring that sampled mirror pixels, each counted once
  // (Frame.accuracy).
  std::uint64_t estimatedFrames = 0;
  double mismatchMean = 0.0, worstMismatchHigh = 0.0, accuracyMsMean = 0.0;
  std::string error;  // empty when the session ran to the end
};

struct LoadReport {
  LoadOptions options;
  std::vector<SessionLoad> sessions;
  double seconds = 0.0;  // measured
  std::uint64_t frames = 0, bytes = 0, skippedFrames = 0, errors = 0;
  double fpsMean = 0.0, fpsMin = 0.0;                           // per session
  double latencyP50 = 0.0, latencyP99 = 0.0, latencyMax = 0.0;  // ms, all sessions together
  double renderMsMean = 0.0, encodeMsMean = 0.0, bytesPerFrame = 0.0;
  // Live accuracy estimates that sampled mirror pixels, all sessions: how many, their mean mismatch, the
  // highest upper bound, CPU ms.
  std::uint64_t estimatedFrames = 0;
  double mismatchMean = 0.0, worstMismatchHigh = 0.0, accuracyMsMean = 0.0;
};

// Runs the load; connection failures are reported per session, not thrown.
LoadReport runLoad(const LoadOptions& options);

// One JSON object (options, aggregate, per-session figures) for automation.
std::string loadReportJson(const LoadReport& report);

}  // namespace specula::client
