// `specula bench`: the scene bench, or the subcommand its first argument names.
#include "app/BenchCommands.h"
#include "app/Commands.h"
#include "base/Subcommands.h"

namespace specula::app {

int runBench(std::span<const std::string> arguments) {
  return runSubcommand(
      "specula bench", "Measures Specula: the scene bench, or one of these.",
      {
          {"tessellation", "tessellation settings against the exact reflection", runTessellationBench},
          {"accuracy", "every method and setting against the ray tracer: error against time", runAccuracyBench},
          {"serve", "streaming: sessions x sizes against real `specula serve` processes", runServeBench},
          {"soak", "minutes of real sessions and misbehaving clients: memory, fds, GL objects, counters", runSoakBench},
      },
      arguments, runSceneBench);
}

}  // namespace specula::app
