#pragma once
// The subcommands of `specula`; each returns the process exit code.
#include <span>
#include <string>

namespace specula::app {

int runRender(std::span<const std::string> arguments);
int runScenes(std::span<const std::string> arguments);
int runBench(std::span<const std::string> arguments);
int runServe(std::span<const std::string> arguments);
int runServeBench(std::span<const std::string> arguments);  // `specula bench serve`

}  // namespace specula::app
