#pragma once
// The adaptive-tessellation options, the same for every command that renders virtual objects.
#include <string>
#include <vector>

#include "base/CommandLine.h"
#include "base/Result.h"
#include "passes/ReflectionSettings.h"

namespace specula::app {

// --tessellation, --metric, --threshold, --level with the defaults of passes::TessellationSettings.
std::vector<OptionSpec> tessellationOptions();

// Reads them, or says which value is wrong and what it accepts.
Result<passes::TessellationSettings> parseTessellationOptions(const CommandLine& options);

}  // namespace specula::app
