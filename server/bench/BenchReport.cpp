#include "bench/BenchReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace specula::bench {

namespace {

std::string number(double value, int decimals) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// Three significant digits: reflection-point errors span 1e-5 px (exact refinement) to pixels.
std::string significant(double value) {
  if (!std::isfinite(value)) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string optionalNumber(const std::optional<double>& value, int decimals) {
  return value ? number(*value, decimals) : "";
}

// Every pass name in the order the passes first ran.
std::vector<std::string> stageNames(std::span<const SceneBenchResult> results) {
  std::vector<std::string> names;
  for (const SceneBenchResult& result : results)
    for (const render::StageTiming& stage : result.stageMedians)
      if (std::find(names.begin(), names.end(), stage.name) == names.end()) names.push_back(stage.name);
  return names;
}

std::optional<double> stageMilliseconds(const SceneBenchResult& result, const std::string& name) {
  for (const render::StageTiming& stage : result.stageMedians)
    if (stage.name == name) return stage.milliseconds;
  return std::nullopt;
}

// The columns shared by CSV and JSON: name and formatted value (empty when not measured).
std::vector<std::pair<std::string, std::string>> fields(const SceneBenchResult& r, std::span<const std::string> stages) {
  std::vector<std::pair<std::string, std::string>> f = {
      {"vertices", std::to_string(r.vertices)},
      {"triangles", std::to_string(r.triangles)},
      {"mirrors", std::to_string(r.mirrors)},
      {"width", std::to_string(r.width)},
      {"height", std::to_string(r.height)},
      {"frames", std::to_string(r.frames)},
      {"first_frame_ms", number(r.firstFrameMilliseconds, 1)},
      {"frame_ms_median", number(r.frameMedianMilliseconds, 2)},
      {"fps", number(r.framesPerSecond(), 1)},
      {"raster_floor_ms", number(r.rasterFloorMilliseconds, 2)},
  };
  for (const std::string& stage : stages) f.push_back({stage + "_ms", optionalNumber(stageMilliseconds(r, stage), 3)});
  f.push_back({"steps_warm_mean", number(r.warmSteps.mean, 2)});
  f.push_back({"steps_warm_max", std::to_string(r.warmSteps.maximum)});
  f.push_back({"steps_cold_mean", number(r.coldSteps.mean, 2)});
  f.push_back({"steps_cold_max", std::to_string(r.coldSteps.maximum)});
  f.push_back({"steps_cold_large_mean", r.coldStepsLarge ? number(r.coldStepsLarge->mean, 2) : ""});
  f.push_back({"steps_cold_large_max", r.coldStepsLarge ? std::to_string(r.coldStepsLarge->maximum) : ""});
  f.push_back({"searched_per_frame", std::to_string(r.searchedPerFrame)});
  f.push_back({"hidden", std::to_string(r.hiddenPerFrame)});
  f.push_back({"unsolved", std::to_string(r.unsolvedPerFrame)});
  f.push_back({"mirror_parts", std::to_string(r.plannedParts)});
  f.push_back({"ray_cast_parts", std::to_string(r.rayCastParts)});
  f.push_back({"searched_frame_ms", optionalNumber(r.searchedFrameMilliseconds, 2)});
  f.push_back({"cast_frame_ms", optionalNumber(r.castFrameMilliseconds, 2)});
  f.push_back({"searched_over_cast", optionalNumber(r.searchedOverCast(), 2)});
  const auto& planner = r.planner;
  f.push_back({"planner_rate_search", planner ? number(planner->rates.search, 3) : ""});
  f.push_back({"planner_rate_cast", planner ? number(planner->rates.rayCast, 3) : ""});
  f.push_back({"planner_predicted_ms", planner ? number(planner->predicted.search + planner->predicted.rayCast, 2) : ""});
  f.push_back({"planner_took_ms", planner ? number(planner->took.search + planner->took.rayCast, 2) : ""});
  f.push_back({"culled_vertices", std::to_string(r.culledVertices)});
  f.push_back({"below_budget_vertices", std::to_string(r.belowBudgetVertices)});
  f.push_back({"uncovered_ray_cast_px", std::to_string(r.uncoveredRayCast)});
  f.push_back({"cast_object_tiles", std::to_string(r.castTiles.listed)});
  f.push_back({"cast_object_tiles_possible", std::to_string(r.castTiles.possible)});
  for (const passes::SearchStrategy strategy : passes::kSearchStrategies) {
    std::string name = passes::searchStrategyName(strategy);
    std::replace(name.begin(), name.end(), '-', '_');  // explosion_map_*: column names are identifiers
    const auto measured = std::find_if(r.searches.begin(), r.searches.end(), [&](const auto& s) { return s.strategy == strategy; });
    const bool has = measured != r.searches.end();
    f.push_back({name + "_search_ms", has ? number(measured->milliseconds, 3) : ""});
    f.push_back({name + "_steps_mean", has ? number(measured->steps.mean, 2) : ""});
    f.push_back({name + "_steps_max", has ? std::to_string(measured->steps.maximum) : ""});
  }
  for (const int samples : SceneBenchResult::kStillSampleCounts) {
    const auto row = std::find_if(r.stillFrames.begin(), r.stillFrames.end(), [&](const auto& s) { return s.samples == samples; });
    f.push_back({"still_ms_" + std::to_string(samples) + "_samples", row != r.stillFrames.end() ? number(row->milliseconds, 1) : ""});
  }
  const auto& e = r.pointError;
  f.push_back({"point_error_count", e ? std::to_string(e->count) : ""});
  f.push_back({"point_error_mean_px", e ? significant(e->mean) : ""});
  f.push_back({"point_error_p99_px", e ? significant(e->p99) : ""});
  f.push_back({"point_error_max_px", e ? significant(e->maximum) : ""});
  f.push_back({"misjudged_hidden", e ? std::to_string(e->misjudgedHidden) : ""});
  f.push_back({"misjudged_visible", e ? std::to_string(e->misjudgedVisible) : ""});
  for (const int factor : SceneBenchResult::kPatchDistanceFactors) {
    const auto row = std::find_if(r.patchTessellation.begin(), r.patchTessellation.end(),
                                  [&](const auto& t) { return t.distanceFactor == factor; });
    const bool has = row != r.patchTessellation.end();
    const std::string suffix = "_at_distance_x" + std::to_string(factor);
    f.push_back({"patch_triangles" + suffix, has ? std::to_string(row->triangles) : ""});
    f.push_back({"patch_area_p10_px" + suffix, has ? number(row->areaP10, 2) : ""});
    f.push_back({"patch_area_p50_px" + suffix, has ? number(row->areaP50, 2) : ""});
    f.push_back({"patch_area_p90_px" + suffix, has ? number(row->areaP90, 2) : ""});
  }
  const auto& c = r.reference;
  f.push_back({"psnr_db", c ? number(c->psnr, 2) : ""});
  f.push_back({"ssim", c ? number(c->ssim, 4) : ""});
  f.push_back({"mirror_mismatch", c ? number(c->mirrorMismatch, 4) : ""});
  f.push_back({"image_samples", c ? std::to_string(c->samples) : ""});
  f.push_back({"raytrace_still_ms", c ? number(c->stillRayTraceMilliseconds, 1) : ""});
  f.push_back({"raytrace_ms", c ? number(c->rayTraceMilliseconds, 1) : ""});
  f.push_back({"frame_vs_raytrace", optionalNumber(r.timeVersusRayTrace(), 3)});
  return f;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string jsonString(const std::string& text) {
  std::string quoted = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += static_cast<char>(c);
    } else if (c < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      quoted += escape;
    } else {
      quoted += static_cast<char>(c);
    }
  }
  return quoted + "\"";
}

std::string orDash(const std::string& text) { return text.empty() ? "-" : text; }

// One CSV row or JSON object: named cells, numbers unless marked as text.
struct Cell {
  std::string name, value;
  bool text = false;
};
using Row = std::vector<Cell>;

Row sceneRow(const SceneBenchResult& r, std::span<const std::string> stages) {
  Row row = {{"scene", r.scene, true}};
  for (auto& [name, value] : fields(r, stages)) row.push_back({std::move(name), std::move(value)});
  return row;
}

// `header` names the columns (its values are ignored).
std::string csvFromRows(const Row& header, std::span<const Row> rows) {
  std::string csv;
  for (std::size_t i = 0; i < header.size(); ++i) csv += (i ? "," : "") + header[i].name;
  csv += "\n";
  for (const Row& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) csv += (i ? "," : "") + csvField(row[i].value);
    csv += "\n";
  }
  return csv;
}

std::string jsonFromRows(const std::string& key, std::span<const Row> rows) {
  std::string json = "{" + jsonString(key) + ": [";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    json += r ? ",\n  {" : "\n  {";
    for (std::size_t i = 0; i < rows[r].size(); ++i) {
      const Cell& cell = rows[r][i];
      json += (i ? ", " : "") + jsonString(cell.name) + ": " +
              (cell.text ? jsonString(cell.value) : cell.value.empty() ? "null" : cell.value);
    }
    json += "}";
  }
  return json + "\n]}\n";
}

Row tessellationRow(const TessellationBenchRow& r) {
  const char* mode = r.tessellation.mode == passes::TessellationMode::None    ? "none"
                     : r.tessellation.mode == passes::TessellationMode::Paper ? "paper"
                                                                              : "crack-free";
  return {{"scene", r.scene, true},
          {"setting", r.setting, true},
          {"mode", mode, true},
          {"metric", r.tessellation.metric == passes::TessellationMetric::Pixels ? "pixels" : "angle", true},
          {"threshold", number(r.tessellation.threshold, 4)},
          {"level", std::to_string(r.tessellation.maxLevel)},
          {"triangles", std::to_string(r.triangles)},
          {"vertices", std::to_string(r.vertices())},
          {"searches", std::to_string(r.searches)},
          {"midpoint_searches", std::to_string(r.midpointSearches)},
          {"capped", r.capped ? "true" : "false"},
          {"frame_ms_median", number(r.frameMilliseconds, 2)},
          {"tessellation_ms_median", number(r.tessellationMilliseconds, 2)},
          {"psnr_db", number(r.psnr, 2)},
          {"ssim", number(r.ssim, 4)},
          {"mirror_mismatch", number(r.mirrorMismatch, 4)}};
}

Row accuracyRow(const AccuracyRow& r) {
  const auto optional = [](const std::optional<double>& value) { return value ? significant(*value) : std::string(); };
  return {{"scene", r.scene, true},
          {"setting", r.setting, true},
          {"family", r.family, true},
          {"frame_ms_median", number(r.frameMilliseconds, 2)},
          {"psnr_db", number(r.psnr, 2)},
          {"ssim", number(r.ssim, 4)},
          {"mirror_mismatch", number(r.mirrorMismatch, 4)},
          {"point_error_p99_px", optional(r.pointErrorP99)},
          {"point_error_max_px", optional(r.pointErrorMax)},
          {"drawn_vertices", std::to_string(r.reflectionVertices)},
          {"searches", std::to_string(r.searches)},
          {"pareto", r.pareto ? "true" : "false"}};
}

// Gnuplot's string syntax: double quotes, backslash escapes.
std::string gnuplotString(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

}  // namespace

std::string formatAccuracyCsv(std::span<const AccuracyRow> rows) {
  std::vector<Row> cells;
  for (const AccuracyRow& row : rows) cells.push_back(accuracyRow(row));
  return csvFromRows(accuracyRow(AccuracyRow{}), cells);
}

std::string formatAccuracyJson(std::span<const AccuracyRow> rows) {
  std::vector<Row> cells;
  for (const AccuracyRow& row : rows) cells.push_back(accuracyRow(row));
  return jsonFromRows("settings", cells);
}

std::string formatAccuracyMarkdown(std::span<const AccuracyRow> rows, const std::string& heading) {
  std::string table = heading + "\n\n"
      "| setting | frame ms | PSNR dB | SSIM | mirror mismatch | point error p99 / max px | drawn vertices | searches |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const AccuracyRow& r : rows) {
    const std::string name = r.pareto ? "**" + r.setting + "**" : r.setting;
    const std::string points = r.pointErrorP99 ? significant(*r.pointErrorP99) + " / " + significant(*r.pointErrorMax) : "-";
    table += "| " + name + " | " + number(r.frameMilliseconds, 1) + " | " + number(r.psnr, 2) + " | " + number(r.ssim, 4) +
             " | " + number(r.mirrorMismatch, 4) + " | " + points + " | " +
             (r.reference ? "-" : std::to_string(r.reflectionVertices)) + " | " + (r.reference ? "-" : std::to_string(r.searches)) +
             " |\n";
  }
  return table + "\nBold: the Pareto front (no other setting is both faster and closer to the reference). "
                 "Frame ms: median over the camera path; errors: means over it.\n";
}

std::string accuracyPlotScript(std::span<const AccuracyRow> rows, const std::string& title, const std::string& pngFile,
                               const std::string& svgFile) {
  // Log axes cannot show 0: a mismatch below this floor is drawn on it.
  static constexpr double kMismatchFloor = 1e-4;
  // Labels closer than this (decades, both axes) to one already placed move down a step.
  constexpr double kLabelWidth = 0.25, kLabelHeight = 0.035;
  struct Point {
    const AccuracyRow* row;
    double x, y, labelY;  // log10 of time, mismatch and the label's height
  };
  std::vector<Point> points;
  double referenceMilliseconds = 0.0;
  for (const AccuracyRow& r : rows) {
    if (r.reference) referenceMilliseconds = r.frameMilliseconds;
    else points.push_back({&r, std::log10(std::max(r.frameMilliseconds, 1e-3)), std::log10(std::max(r.mirrorMismatch, kMismatchFloor)), 0.0});
  }
  if (points.empty()) return "# no settings to plot\n";
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.y > b.y; });
  for (std::size_t i = 0; i < points.size(); ++i) {
    Point& p = points[i];
    p.labelY = p.y;
    // Each move goes strictly lower (by a little more than a label, so rounding cannot undo it): at most i moves.
    for (std::size_t moves = 0; moves <= i; ++moves) {
      const auto clash = std::find_if(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(i), [&](const Point& q) {
        return std::abs(q.x - p.x) < kLabelWidth && std::abs(q.labelY - p.labelY) < kLabelHeight;
      });
      if (clash == points.begin() + static_cast<std::ptrdiff_t>(i)) break;
      p.labelY = clash->labelY - 1.001 * kLabelHeight;
    }
  }
  double minX = std::log10(std::max(referenceMilliseconds, 1e-3)), maxX = minX, minY = points.front().labelY, maxY = minY;
  for (const Point& p : points) {
    minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
    minY = std::min({minY, p.y, p.labelY}), maxY = std::max(maxY, p.y);
  }
  const auto position = [](const AccuracyRow& r) {
    return number(r.frameMilliseconds, 3) + " " + number(std::max(r.mirrorMismatch, kMismatchFloor), 6);
  };
  std::string data, front;
  std::vector<const Point*> pareto;
  for (const Point& p : points) {
    data += position(*p.row) + " " + number(std::pow(10.0, p.labelY), 6) + " " + gnuplotString(p.row->setting) + "\n";
    if (p.row->pareto) pareto.push_back(&p);
  }
  std::sort(pareto.begin(), pareto.end(), [](const Point* a, const Point* b) { return a->x < b->x; });
  for (const Point* p : pareto) front += position(*p->row) + "\n";
  const auto power = [](double exponent) { return number(std::pow(10.0, exponent), 6); };
  std::string script = "# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>\n";
  script += "# settings: frame ms, mirror mismatch, label height, name\n";
  script += "$settings << EOD\n" + data + "EOD\n$front << EOD\n" + front + "EOD\n";
  script += "set title " + gnuplotString(title) + " noenhanced\n"
            "set xlabel 'frame time, ms (median over the camera path; log scale)'\n"
            "set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'\n"
            "set logscale xy\nset format x '%g'\nset format y '%g'\nset grid\nset key top right box opaque\n";
  // Room on the right for the labels, a margin elsewhere.
  script += "set xrange [" + power(minX - 0.1) + ":" + power(maxX + 0.45) + "]\nset yrange [" + power(minY - 0.15) + ":" +
            power(maxY + 0.15) + "]\n";
  script += "set arrow 1 from " + number(referenceMilliseconds, 3) + ", graph 0 to " + number(referenceMilliseconds, 3) +
            ", graph 1 nohead dashtype 2 linecolor rgb '#444444'\n";
  script += "set label 1 " + gnuplotString("ray-traced reference: " + number(referenceMilliseconds, 0) + " ms, error 0") + " at " +
            number(referenceMilliseconds, 3) + ", graph 0.25 rotate by 90 offset -1, 0 center noenhanced\n";
  const bool onTheFloor = std::any_of(points.begin(), points.end(), [](const Point& p) { return p.row->mirrorMismatch < kMismatchFloor; });
  if (onTheFloor)
    script += "set label 2 " + gnuplotString("mismatch under " + number(kMismatchFloor, 4) + " (exact included) is drawn on this line") +
              " at graph 0.99, first " + number(kMismatchFloor, 6) + " right offset 0, 0.8 font ',8' textcolor rgb '#444444' noenhanced\n";
  const std::string plot =
      "plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title 'Pareto front', \\\n"
      "     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \\\n"
      "     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle\n";
  script += "set terminal pngcairo size 1100,750 font ',10'\nset output " + gnuplotString(pngFile) + "\n" + plot;
  script += "set terminal svg size 1100,750 dynamic font ',10'\nset output " + gnuplotString(svgFile) + "\n" + plot;
  return script + "unset output\n";
}

std::string formatCsv(std::span<const SceneBenchResult> results) {
  const std::vector<std::string> stages = stageNames(results);
  std::vector<Row> rows;
  for (const SceneBenchResult& result : results) rows.push_back(sceneRow(result, stages));
  return csvFromRows(sceneRow(SceneBenchResult{}, stages), rows);
}

std::string formatJson(std::span<const SceneBenchResult> results) {
  const std::vector<std::string> stages = stageNames(results);
  std::vector<Row> rows;
  for (const SceneBenchResult& result : results) rows.push_back(sceneRow(result, stages));
  return jsonFromRows("scenes", rows);
}

std::string formatTable(std::span<const SceneBenchResult> results) {
  std::string table;
  char line[512];
  std::snprintf(line, sizeof line, "%-16s %8s %7s %6s %6s | %-17s | %-26s | %-20s | %8s %8s\n", "scene", "frame ms", "fps",
                "first", "floor", "steps warm/cold/L", "point error mean/p99/max", "PSNR/SSIM/mismatch", "trace ms", "x trace");
  table += line;
  for (const SceneBenchResult& r : results) {
    const auto& e = r.pointError;
    const auto& c = r.reference;
    const std::string steps = number(r.warmSteps.mean, 1) + "/" + number(r.coldSteps.mean, 1) + "/" +
                              orDash(r.coldStepsLarge ? number(r.coldStepsLarge->mean, 1) : "");
    const std::string error = e ? significant(e->mean) + "/" + significant(e->p99) + "/" + significant(e->maximum) : "-";
    const std::string image = c ? number(c->psnr, 1) + "/" + number(c->ssim, 3) + "/" + number(c->mirrorMismatch, 3) : "-";
    std::snprintf(line, sizeof line, "%-16.40s %8s %7s %6s %6s | %-17s | %-26s | %-20s | %8s %8s\n", r.scene.c_str(),
                  number(r.frameMedianMilliseconds, 1).c_str(), number(r.framesPerSecond(), 1).c_str(),
                  number(r.firstFrameMilliseconds, 0).c_str(), number(r.rasterFloorMilliseconds, 1).c_str(), steps.c_str(), error.c_str(), image.c_str(),
                  orDash(c ? number(c->rayTraceMilliseconds, 0) : "").c_str(),
                  orDash(optionalNumber(r.timeVersusRayTrace(), 2)).c_str());
    table += line;
    std::string passes = "  passes (median ms):";
    for (const render::StageTiming& stage : r.stageMedians) passes += " " + stage.name + " " + number(stage.milliseconds, 2);
    table += passes + "\n";
    table += "  plan (last frame): " + std::to_string(r.plannedParts) + " mirror parts, " + std::to_string(r.rayCastParts) +
             " ray-cast, " + std::to_string(r.culledVertices) + " reflected vertices left out, " +
             std::to_string(r.belowBudgetVertices) + " under the error budget, " + std::to_string(r.uncoveredRayCast) +
             " uncovered pixels ray-cast, cast on " + std::to_string(r.castTiles.listed) + " of " +
             std::to_string(r.castTiles.possible) + " object tiles\n";
    if (r.searchedOverCast())
      table += "  searched / cast at " + std::to_string(r.width) + "x" + std::to_string(r.height) + ": " + number(*r.searchedOverCast(), 2) + " (every part searched " + number(*r.searchedFrameMilliseconds, 1) +
               " ms a frame, every part cast " + number(*r.castFrameMilliseconds, 1) + " ms; medians of 10 warm frames)\n";
    if (r.planner) {
      const auto& p = *r.planner;
      table += "  planner (last measured frame): searching predicted " + number(p.predicted.search, 1) + " ms, took " +
               number(p.took.search, 1) + "; ray-casting predicted " + number(p.predicted.rayCast, 1) + " ms, took " +
               number(p.took.rayCast, 1) + "; rates measured here over the llvmpipe fit: searching " + number(p.rates.search, 2) +
               ", ray-casting " + number(p.rates.rayCast, 2) + "\n";
    }
    if (!r.stillFrames.empty()) {
      std::string still = "  still frames (last pose, samples a pixel: ms):";
      for (const SceneBenchResult::StillFrame& s : r.stillFrames) still += " " + std::to_string(s.samples) + ": " + number(s.milliseconds, 1) + ";";
      if (c) still += " images compared at " + std::to_string(c->samples) + " samples with a " + std::to_string(c->samples) + "-ray trace (" + number(c->stillRayTraceMilliseconds, 0) + " ms);";
      still.back() = '\n';
      table += still;
    }
    if (!r.patchTessellation.empty()) {
      std::string patches = "  patch tessellation (last pose, camera distance ×):";
      for (const SceneBenchResult::PatchTessellation& t : r.patchTessellation)
        patches += " " + std::to_string(t.distanceFactor) + ": " + std::to_string(t.triangles) + " triangles, pixel area " +
                   number(t.areaP10, 1) + "/" + number(t.areaP50, 1) + "/" + number(t.areaP90, 1) + ";";
      patches.back() = '\n';
      table += patches;
    }
    if (r.searches.empty()) continue;
    std::string searches = "  searches (first frames, warm):";
    for (const SceneBenchResult::SearchComparison& s : r.searches) {
      searches += std::string(" ") + passes::searchStrategyName(s.strategy) + " " + number(s.milliseconds, 2) + " ms, " +
                  number(s.steps.mean, 1) + " steps (max " + std::to_string(s.steps.maximum) + ")";
      if (s.strategy == passes::SearchStrategy::Hierarchy)
        searches += ", " + std::to_string(s.enlarged) + " enlarged, " + std::to_string(s.inNoCone) + " in no cone";
      searches += ";";
    }
    searches.back() = '\n';
    table += searches;
  }
  return table;
}


std::string formatTessellationCsv(std::span<const TessellationBenchRow> rows) {
  std::vector<Row> cells;
  for (const TessellationBenchRow& row : rows) cells.push_back(tessellationRow(row));
  return csvFromRows(tessellationRow(TessellationBenchRow{}), cells);
}

std::string formatTessellationJson(std::span<const TessellationBenchRow> rows) {
  std::vector<Row> cells;
  for (const TessellationBenchRow& row : rows) cells.push_back(tessellationRow(row));
  return jsonFromRows("settings", cells);
}

std::string formatTessellationTable(std::span<const TessellationBenchRow> rows) {
  std::string table;
  char line[512];
  std::snprintf(line, sizeof line, "%-16s %-34s %10s %10s %10s %9s %8s | %-20s\n", "scene", "tessellation", "triangles",
                "vertices", "searches", "frame ms", "tess ms", "PSNR/SSIM/mismatch");
  table += line;
  for (const TessellationBenchRow& r : rows) {
    const std::string image = number(r.psnr, 1) + "/" + number(r.ssim, 3) + "/" + number(r.mirrorMismatch, 3);
    std::snprintf(line, sizeof line, "%-16.40s %-34.40s %10u %10u %10u %9s %8s | %-20s%s\n", r.scene.c_str(),
                  r.setting.c_str(), r.triangles, r.vertices(), r.searches, number(r.frameMilliseconds, 1).c_str(),
                  number(r.tessellationMilliseconds, 1).c_str(), image.c_str(), r.capped ? "  (capped)" : "");
    table += line;
  }
  return table;
}

}  // namespace specula::bench
