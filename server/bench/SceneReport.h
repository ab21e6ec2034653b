#pragma once
// `specula bench` results, a scene per row, as a table for people and as CSV and JSON for scripts and
// plots. Times in milliseconds, errors in pixels.
#include <span>
#include <string>

#include "bench/SceneBenchmark.h"

namespace specula::bench {

std::string formatTable(std::span<const SceneBenchResult> results);
// One row per scene; one `<pass>_ms` column per pass that ran in any scene.
std::string formatCsv(std::span<const SceneBenchResult> results);
// {"scenes": [...]} with one object per scene.
std::string formatJson(std::span<const SceneBenchResult> results);

}  // namespace specula::bench
