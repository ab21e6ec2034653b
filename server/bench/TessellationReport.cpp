#include "bench/TessellationReport.h"

#include <cstdio>
#include <vector>

#include "bench/ReportFormat.h"

namespace specula::bench {

namespace {

ReportRow tessellationRow(const TessellationBenchRow& r) {
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

std::vector<ReportRow> tessellationRows(std::span<const TessellationBenchRow> rows) {
  std::vector<ReportRow> cells;
  for (const TessellationBenchRow& row : rows) cells.push_back(tessellationRow(row));
  return cells;
}

}  // namespace

std::string formatTessellationCsv(std::span<const TessellationBenchRow> rows) {
  return csvFromRows(tessellationRow(TessellationBenchRow{}), tessellationRows(rows));
}

std::string formatTessellationJson(std::span<const TessellationBenchRow> rows) {
  return jsonFromRows("settings", tessellationRows(rows));
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
