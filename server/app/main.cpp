// `specula`: the one executable; the only place where the modules are wired together.
#include <iostream>
#include <string>
#include <vector>

#include "app/Commands.h"

namespace {

constexpr const char* kUsage =
    "usage: specula <command> [options]\n"
    "\n"
    "Specula renders accurate reflections on curved mirrors, headless (EGL on a GPU, or Mesa's software GL).\n"
    "\n"
    "commands:\n"
    "  serve     stream a scene to browsers and thin clients over HTTP + WebSocket (JPEG frames)\n"
    "  render    render one frame of a scene to a PNG or JPEG file and print per-stage timings\n"
    "  scenes    list the built-in scenes\n"
    "  bench     measure time per pass, search steps and accuracy against exact references; CSV and JSON\n"
    "\n"
    "Run `specula <command> --help` for a command's options.\n";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h" || arguments[0] == "help") {
    std::cout << kUsage;
    return arguments.empty() ? 2 : 0;
  }
  const std::string& command = arguments[0];
  const std::span<const std::string> rest(arguments.begin() + 1, arguments.end());
  if (command == "render") return specula::app::runRender(rest);
  if (command == "scenes") return specula::app::runScenes(rest);
  if (command == "bench") return specula::app::runBench(rest);
  if (command == "serve") return specula::app::runServe(rest);
  std::cerr << "specula: unknown command '" << command << "'\n\n" << kUsage;
  return 2;
}
