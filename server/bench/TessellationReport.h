#pragma once
// `specula bench tessellation` results, a (scene, setting) per row, as a table, CSV and JSON
// ({"settings": [...]}). Times in milliseconds.
#include <span>
#include <string>

#include "bench/TessellationBenchmark.h"

namespace specula::bench {

std::string formatTessellationTable(std::span<const TessellationBenchRow> rows);
std::string formatTessellationCsv(std::span<const TessellationBenchRow> rows);
std::string formatTessellationJson(std::span<const TessellationBenchRow> rows);

}  // namespace specula::bench
