#include "ViewerOptions.h"

#include <initializer_list>
#include <vector>

namespace specula::view {

CommandLine viewerCommandLine() {
  std::vector<OptionSpec> specs = client::connectionOptions();
  for (OptionSpec spec : std::initializer_list<OptionSpec>{
           {"size", "WxH", "window size", "960x540"},
           {"frames", "N", "exit after drawing N frames (0: never)", "0"},
           {"seconds", "S", "exit after S seconds (0: never)", "0"},
           {"screenshot", "FILE.png", "on exit, save what the window showed last", ""},
       })
    specs.push_back(spec);
  return CommandLine(
      "specula-view [options]",
      "Opens a window on a Specula server's stream. Drag: orbit; right-drag or shift-drag: pan; wheel: zoom;\n"
      "arrows: orbit; +/-: zoom; space: play/pause; Esc: quit. Statistics are in the window title and printed\n"
      "once a second. --frames or --seconds end the run (scripts, tests).",
      std::move(specs));
}

Result<ViewerOptions> readViewerOptions(const CommandLine& options) {
  auto connection = client::parseConnectionOptions(options);
  auto size = options.size("size", 8192);
  auto frameLimit = options.integer("frames", 0, 1 << 30);
  auto seconds = options.number("seconds");
  if (!connection) return Error{connection.error()};
  if (!size) return Error{size.error()};
  if (!frameLimit) return Error{frameLimit.error()};
  if (!seconds || *seconds < 0.0) return Error{"--seconds expects a number >= 0"};
  ViewerOptions viewer{*connection, *size, *frameLimit, *seconds, std::nullopt};
  if (options.has("screenshot")) viewer.screenshot = options.text("screenshot");
  return viewer;
}

}  // namespace specula::view
