#pragma once
// `specula bench accuracy` results, a setting per row, as CSV, JSON ({"settings": [...]}), a Markdown
// table and a gnuplot script. Times in milliseconds, errors in pixels.
#include <span>
#include <string>

#include "bench/AccuracyBenchmark.h"

namespace specula::bench {

std::string formatAccuracyCsv(std::span<const AccuracyRow> rows);
std::string formatAccuracyJson(std::span<const AccuracyRow> rows);
// A Markdown table under `heading` (Pareto rows in bold).
std::string formatAccuracyMarkdown(std::span<const AccuracyRow> rows, const std::string& heading);

// A self-contained gnuplot script (data inline) that draws mirror mismatch against frame time, both
// log scales, every setting labelled, the Pareto front as a line and the ray tracer's time as a
// vertical line; it writes `pngFile` and `svgFile` relative to gnuplot's working folder.
std::string accuracyPlotScript(std::span<const AccuracyRow> rows, const std::string& title, const std::string& pngFile,
                               const std::string& svgFile);

}  // namespace specula::bench
