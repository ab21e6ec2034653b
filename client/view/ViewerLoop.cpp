#include "ViewerLoop.h"

#include <chrono>
#include <cstdio>
#include <optional>

#include "JpegDecoder.h"

namespace specula::view {

namespace {

using Clock = std::chrono::steady_clock;

std::string statisticsLine(const v1::Frame& shown, std::uint64_t framesPerSecond, double latencyMs) {
  char line[256];
  std::snprintf(line, sizeof line,
                "Specula  %ux%u  %llu fps  input->frame %.0f ms  render %.1f ms  encode %.1f ms  search %u vertices "
                "%.2f steps  tessellation %u->%u",
                shown.width(), shown.height(), static_cast<unsigned long long>(framesPerSecond), latencyMs,
                shown.render_ms(), shown.encode_ms(), shown.search().searched(), shown.search().mean_steps(),
                shown.tessellation().input_triangles(), shown.tessellation().finished_triangles());
  return line;
}

}  // namespace

LoopOutcome runViewerLoop(ViewerWindow& window, Link& link, CameraInput& input, const ViewerOptions& options) {
  JpegDecoder decoder;
  RgbaImage image;
  LoopOutcome outcome;
  std::uint64_t framesThisSecond = 0;
  double latencyMs = 0.0;
  std::optional<v1::Frame> shown;
  const Clock::time_point start = Clock::now();
  Clock::time_point secondStart = start;
  while (!window.shouldClose()) {
    window.pollEvents();
    std::optional<v1::Frame> frame;
    {
      std::lock_guard lock(link.mutex);
      frame.swap(link.latestFrame);
      outcome.problem = link.problem;
    }
    if (!outcome.problem.empty()) break;
    if (frame && decoder.decode(frame->jpeg(), image)) {
      window.show(image);
      ++outcome.drawn;
      ++framesThisSecond;
      if (std::optional<double> latency = input.frameShown(*frame)) latencyMs = *latency;
      shown = std::move(frame);
    }
    window.present();

    const Clock::time_point now = Clock::now();
    if (now - secondStart >= std::chrono::seconds(1) && shown) {
      const std::string line = statisticsLine(*shown, framesThisSecond, latencyMs);
      window.setTitle(line);
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
      framesThisSecond = 0;
      secondStart = now;
    }
    if (options.frameLimit > 0 && outcome.drawn >= static_cast<std::uint64_t>(options.frameLimit)) break;
    if (options.seconds > 0.0 && now - start >= std::chrono::duration<double>(options.seconds)) break;
  }
  return outcome;
}

}  // namespace specula::view
