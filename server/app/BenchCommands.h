#pragma once
// The subcommands of `specula bench` (`bench serve` is in Commands.h) and what they share.
#include <span>
#include <string>

#include "base/CommandFailure.h"

namespace specula::app {

int runSceneBench(std::span<const std::string> arguments);         // `specula bench`
int runTessellationBench(std::span<const std::string> arguments);  // `specula bench tessellation`
int runAccuracyBench(std::span<const std::string> arguments);      // `specula bench accuracy`
int runSoakBench(std::span<const std::string> arguments);          // `specula bench soak`

constexpr int kMaxBenchSide = 4096;
constexpr int kMaxFrames = 10000;

constexpr CommandFailure fail{"specula bench"};

}  // namespace specula::app
