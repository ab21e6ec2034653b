#pragma once
// `specula bench` results as a table for people and as CSV and JSON for scripts and plots.
// Times in milliseconds, errors in pixels; a value that was not measured is an empty CSV cell,
// a JSON null and "-" in the table.
#include <span>
#include <string>

#include "bench/AccuracyBenchmark.h"
#include "bench/SceneBenchmark.h"
#include "bench/TessellationBenchmark.h"

namespace specula::bench {

std::string formatTable(std::span<const SceneBenchResult> results);
// One row per scene; one `<pass>_ms` column per pass that ran in any scene.
std::string formatCsv(std::span<const SceneBenchResult> results);
// {"scenes": [...]} with one object per scene.
std::string formatJson(std::span<const SceneBenchResult> results);

// `specula bench tessellation`: one row per (scene, setting); JSON as {"settings": [...]}.
std::string formatTessellationTable(std::span<const TessellationBenchRow> rows);
std::string formatTessellationCsv(std::span<const TessellationBenchRow> rows);
std::string formatTessellationJson(std::span<const TessellationBenchRow> rows);

// `specula bench accuracy`: one row per setting; JSON as {"settings": [...]}; a Markdown table
// under `heading` (Pareto rows in bold).
std::string formatAccuracyCsv(std::span<const AccuracyRow> rows);
std::string formatAccuracyJson(std::span<const AccuracyRow> rows);
std::string formatAccuracyMarkdown(std::span<const AccuracyRow> rows, const std::string& heading);

// A self-contained gnuplot script (data inline) that draws mirror mismatch against frame time, both
// log scales, every setting labelled, the Pareto front as a line and the ray tracer's time as a
// vertical line; it writes `pngFile` and `svgFile` relative to gnuplot's working folder.
std::string accuracyPlotScript(std::span<const AccuracyRow> rows, const std::string& title, const std::string& pngFile,
                               const std::string& svgFile);

}  // namespace specula::bench
