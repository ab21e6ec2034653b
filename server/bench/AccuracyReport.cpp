#include "bench/AccuracyReport.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "bench/ReportFormat.h"

namespace specula::bench {

namespace {

ReportRow accuracyRow(const AccuracyRow& r) {
  const auto optional = [](const std::optional<double>& value) { return value ? significant(*value) : std::string(); };
  return {{"scene", r.scene, true},
          {"setting", r.setting, true},
          {"family", r.family, true},
          {"frame_ms_median", number(r.frameMilliseconds, 2)},
          {"psnr_db", number(r.psnr, 2)},
          {"ssim", number(r.ssim, 4)},
          {"mirror_mismatch", number(r.mirrorMismatch, 4)},
          {"estimate_mean", r.reference ? "" : number(r.estimateMean, 4)},
          {"estimate_coverage", r.reference ? "" : number(r.estimateCoverage, 3)},
          {"estimate_ms", r.reference ? "" : number(r.estimateMilliseconds, 2)},
          {"point_error_p99_px", optional(r.pointErrorP99)},
          {"point_error_max_px", optional(r.pointErrorMax)},
          {"drawn_vertices", std::to_string(r.reflectionVertices)},
          {"searches", std::to_string(r.searches)},
          {"pareto", r.pareto ? "true" : "false"}};
}

std::vector<ReportRow> accuracyRows(std::span<const AccuracyRow> rows) {
  std::vector<ReportRow> cells;
  for (const AccuracyRow& row : rows) cells.push_back(accuracyRow(row));
  return cells;
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
  return csvFromRows(accuracyRow(AccuracyRow{}), accuracyRows(rows));
}

std::string formatAccuracyJson(std::span<const AccuracyRow> rows) {
  return jsonFromRows("settings", accuracyRows(rows));
}

std::string formatAccuracyMarkdown(std::span<const AccuracyRow> rows, const std::string& heading) {
  std::string table = heading +
                      "\n\n"
                      "| setting | frame ms | PSNR dB | SSIM | mirror mismatch | live estimate (covered) | point error "
                      "p99 / max px | drawn vertices | searches |\n"
                      "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const AccuracyRow& r : rows) {
    const std::string name = r.pareto ? "**" + r.setting + "**" : r.setting;
    const std::string points =
        r.pointErrorP99 ? significant(*r.pointErrorP99) + " / " + significant(*r.pointErrorMax) : "-";
    table += "| " + name + " | " + number(r.frameMilliseconds, 1) + " | " + number(r.psnr, 2) + " | " +
             number(r.ssim, 4) + " | " + number(r.mirrorMismatch, 4) + " | " +
             (r.reference ? "-" : number(r.estimateMean, 4) + " (" + number(100.0 * r.estimateCoverage, 0) + " %)") +
             " | " + points + " | " + (r.reference ? "-" : std::to_string(r.reflectionVertices)) + " | " +
             (r.reference ? "-" : std::to_string(r.searches)) + " |\n";
  }
  return table +
         "\nBold: the Pareto front (no other setting is both faster and closer to the reference). "
         "Frame ms: median over the camera path; errors: means over it. Live estimate: the mean of what a "
         "stream reports per frame (256 mirror pixels traced exactly), and in how many frames its 95 % interval "
         "held the full comparison's mismatch.\n";
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
    else
      points.push_back({&r, std::log10(std::max(r.frameMilliseconds, 1e-3)),
                        std::log10(std::max(r.mirrorMismatch, kMismatchFloor)), 0.0});
  }
  if (points.empty()) return "# no settings to plot\n";
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.y > b.y; });
  for (std::size_t i = 0; i < points.size(); ++i) {
    Point& p = points[i];
    p.labelY = p.y;
    // Each move goes strictly lower (by a little more than a label, so rounding cannot undo it): at most i moves.
    for (std::size_t moves = 0; moves <= i; ++moves) {
      const auto clash =
          std::find_if(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(i), [&](const Point& q) {
            return std::abs(q.x - p.x) < kLabelWidth && std::abs(q.labelY - p.labelY) < kLabelHeight;
          });
      if (clash == points.begin() + static_cast<std::ptrdiff_t>(i)) break;
      p.labelY = clash->labelY - 1.001 * kLabelHeight;
    }
  }
  double minX = std::log10(std::max(referenceMilliseconds, 1e-3)), maxX = minX, minY = points.front().labelY,
         maxY = minY;
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
  script += "set title " + gnuplotString(title) +
            " noenhanced\n"
            "set xlabel 'frame time, ms (median over the camera path; log scale)'\n"
            "set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'\n"
            "set logscale xy\nset format x '%g'\nset format y '%g'\nset grid\nset key top right box opaque\n";
  // Room on the right for the labels, a margin elsewhere.
  script += "set xrange [" + power(minX - 0.1) + ":" + power(maxX + 0.45) + "]\nset yrange [" + power(minY - 0.15) +
            ":" + power(maxY + 0.15) + "]\n";
  script += "set arrow 1 from " + number(referenceMilliseconds, 3) + ", graph 0 to " +
            number(referenceMilliseconds, 3) + ", graph 1 nohead dashtype 2 linecolor rgb '#444444'\n";
  script += "set label 1 " +
            gnuplotString("ray-traced reference: " + number(referenceMilliseconds, 0) + " ms, error 0") + " at " +
            number(referenceMilliseconds, 3) + ", graph 0.25 rotate by 90 offset -1, 0 center noenhanced\n";
  const bool onTheFloor =
      std::any_of(points.begin(), points.end(), [](const Point& p) { return p.row->mirrorMismatch < kMismatchFloor; });
  if (onTheFloor)
    script += "set label 2 " +
              gnuplotString("mismatch under " + number(kMismatchFloor, 4) + " (exact included) is drawn on this line") +
              " at graph 0.99, first " + number(kMismatchFloor, 6) +
              " right offset 0, 0.8 font ',8' textcolor rgb '#444444' noenhanced\n";
  const std::string plot =
      "plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title "
      "'Pareto front', \\\n"
      "     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \\\n"
      "     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle\n";
  script += "set terminal pngcairo size 1100,750 font ',10'\nset output " + gnuplotString(pngFile) + "\n" + plot;
  script += "set terminal svg size 1100,750 dynamic font ',10'\nset output " + gnuplotString(svgFile) + "\n" + plot;
  return script + "unset output\n";
}

}  // namespace specula::bench
