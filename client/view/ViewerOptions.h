#pragma once
// specula-view's command line: the server to connect to, the window size and when to stop.
#include <optional>
#include <string>
#include <utility>

#include "ConnectionOptions.h"
#include "base/CommandLine.h"

namespace specula::view {

struct ViewerOptions {
  client::Connection connection;
  std::pair<int, int> size;               // of the window, in screen coordinates
  int frameLimit = 0;                     // exit after drawing this many frames; 0: never
  double seconds = 0.0;                   // exit after this long; 0: never
  std::optional<std::string> screenshot;  // PNG file that gets the window's last picture on exit
};

// The option table, which --help prints.
CommandLine viewerCommandLine();
// The parsed options, or the first one that is wrong and what it expects.
Result<ViewerOptions> readViewerOptions(const CommandLine& options);

}  // namespace specula::view
