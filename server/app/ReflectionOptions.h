#pragma once
// The reflection options, the same for every command that renders virtual objects.
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

// --search (crosshair, hierarchy or explosion-map), the explosion map's size, refinement and placement,
// --virtual-pixels, and --extrusions (solve or search the mirrors declared as extrusions).
std::vector<OptionSpec> searchOptions();

// Reads them into `settings`, or says which value is wrong and what it accepts.
Status parseSearchOptions(const CommandLine& options, passes::ReflectionSettings& settings);

// --plan and --ray-cast: what the frame plan leaves out and which mirror parts it ray-casts (none
// when --search, or --method explosion-map, names the method and --ray-cast is not given).
std::vector<OptionSpec> planOptions();

// Reads them into `settings`, or says which value is wrong and what it accepts.
Status parsePlanOptions(const CommandLine& options, passes::ReflectionSettings& settings);

// The search, tessellation and plan options plus --margin, --gbuffer-scale, --gbuffer-precision and --environment-size.
std::vector<OptionSpec> reflectionOptions();

// Reads them all (the method stays the default: each command names its own methods).
Result<passes::ReflectionSettings> parseReflectionOptions(const CommandLine& options);

// --samples N: anti-aliasing, rays or jittered frames per pixel (math::samplePattern), `fallback` by default.
OptionSpec samplesOption(int fallback, const std::string& what = "anti-aliasing: samples per pixel, 1, 2, 4, 8 or 16 (every method takes the same points)");
Result<int> parseSamples(const CommandLine& options, const std::string& name = "samples");

}  // namespace specula::app
