#pragma once
// Drawing benchmark plots with gnuplot, a separate program: found on PATH, run without a shell.
#include <string>

#include "base/Result.h"

namespace specula::app {

// The fix to print when gnuplot is missing.
inline constexpr const char* kInstallGnuplot =
    "install gnuplot with `apt-get install gnuplot-nox` (docker/install-deps.sh does)";

bool gnuplotAvailable();

// Runs `gnuplot scriptFile` in `folder` (the script's outputs are relative to it); fails naming
// gnuplot's exit status, its output being on stderr already.
Status runGnuplot(const std::string& folder, const std::string& scriptFile);

}  // namespace specula::app
