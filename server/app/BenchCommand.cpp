// `specula bench`: the scene bench, or the subcommand its first argument names.
#include "app/BenchCommands.h"
#include "app/Commands.h"

namespace specula::app {

int runBench(std::span<const std::string> arguments) {
  const std::string subcommand = arguments.empty() ? "" : arguments.front();
  if (subcommand == "tessellation") return runTessellationBench(arguments.subspan(1));
  if (subcommand == "accuracy") return runAccuracyBench(arguments.subspan(1));
  if (subcommand == "serve") return runServeBench(arguments.subspan(1));
  return runSceneBench(arguments);
}

}  // namespace specula::app
