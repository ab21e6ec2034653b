// `specula`: the one executable; the only place where the modules are wired together.
#include <string>
#include <vector>

#include "app/Commands.h"
#include "base/Subcommands.h"

int main(int argc, char** argv) {
  using namespace specula::app;
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  return specula::runSubcommand(
      "specula",
      "Specula renders accurate reflections on curved mirrors, headless (EGL on a GPU, or Mesa's software GL).",
      {
          {"serve", "stream a scene to browsers and thin clients over HTTP + WebSocket (JPEG frames)", runServe},
          {"render", "render one frame of a scene to a PNG or JPEG file and print per-stage timings", runRender},
          {"scenes", "list the built-in scenes", runScenes},
          {"bench", "measure time per pass, search steps and accuracy against exact references; CSV and JSON",
           runBench},
      },
      arguments);
}
