#pragma once
// The window thread's loop: shows each new frame, and once a second puts fps, latency, server timings and
// search/tessellation statistics in the window title and on stdout.
#include <cstdint>
#include <string>

#include "CameraInput.h"
#include "ServerLink.h"
#include "ViewerOptions.h"
#include "ViewerWindow.h"

namespace specula::view {

struct LoopOutcome {
  std::uint64_t drawn = 0;  // frames shown
  std::string problem;      // why the connection failed; empty when the window closed or a limit was reached
};

// Runs until the window closes, --frames or --seconds is reached, or the connection fails.
LoopOutcome runViewerLoop(ViewerWindow& window, Link& link, CameraInput& input, const ViewerOptions& options);

}  // namespace specula::view
