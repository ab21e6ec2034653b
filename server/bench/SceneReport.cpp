#include "bench/SceneReport.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "bench/ReportFormat.h"

namespace specula::bench {

namespace {

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

// The columns shared by CSV and JSON.
ReportRow sceneRow(const SceneBenchResult& r, std::span<const std::string> stages) {
  ReportRow cells = {
      {"scene", r.scene, true},
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
  for (const std::string& stage : stages)
    cells.push_back({stage + "_ms", optionalNumber(stageMilliseconds(r, stage), 3)});
  cells.push_back({"steps_warm_mean", number(r.warmSteps.mean, 2)});
  cells.push_back({"steps_warm_max", std::to_string(r.warmSteps.maximum)});
  cells.push_back({"steps_cold_mean", number(r.coldSteps.mean, 2)});
  cells.push_back({"steps_cold_max", std::to_string(r.coldSteps.maximum)});
  cells.push_back({"steps_cold_large_mean", r.coldStepsLarge ? number(r.coldStepsLarge->mean, 2) : ""});
  cells.push_back({"steps_cold_large_max", r.coldStepsLarge ? std::to_string(r.coldStepsLarge->maximum) : ""});
  cells.push_back({"searched_per_frame", std::to_string(r.searchedPerFrame)});
  cells.push_back({"hidden", std::to_string(r.hiddenPerFrame)});
  cells.push_back({"unsolved", std::to_string(r.unsolvedPerFrame)});
  cells.push_back({"mirror_parts", std::to_string(r.plannedParts)});
  cells.push_back({"ray_cast_parts", std::to_string(r.rayCastParts)});
  cells.push_back({"searched_frame_ms", optionalNumber(r.searchedFrameMilliseconds, 2)});
  cells.push_back({"cast_frame_ms", optionalNumber(r.castFrameMilliseconds, 2)});
  cells.push_back({"searched_over_cast", optionalNumber(r.searchedOverCast(), 2)});
  const auto& planner = r.planner;
  cells.push_back({"planner_rate_search", planner ? number(planner->rates.search, 3) : ""});
  cells.push_back({"planner_rate_cast", planner ? number(planner->rates.rayCast, 3) : ""});
  cells.push_back(
      {"planner_predicted_ms", planner ? number(planner->predicted.search + planner->predicted.rayCast, 2) : ""});
  cells.push_back({"planner_took_ms", planner ? number(planner->took.search + planner->took.rayCast, 2) : ""});
  cells.push_back({"culled_vertices", std::to_string(r.culledVertices)});
  cells.push_back({"below_budget_vertices", std::to_string(r.belowBudgetVertices)});
  cells.push_back({"uncovered_ray_cast_px", std::to_string(r.uncoveredRayCast)});
  cells.push_back({"cast_object_tiles", std::to_string(r.castTiles.listed)});
  cells.push_back({"cast_object_tiles_possible", std::to_string(r.castTiles.possible)});
  for (const passes::SearchStrategy strategy : passes::kSearchStrategies) {
    std::string name = passes::searchStrategyName(strategy);
    std::replace(name.begin(), name.end(), '-', '_');  // explosion_map_*: column names are identifiers
    const auto measured =
        std::find_if(r.searches.begin(), r.searches.end(), [&](const auto& s) { return s.strategy == strategy; });
    const bool has = measured != r.searches.end();
    cells.push_back({name + "_search_ms", has ? number(measured->milliseconds, 3) : ""});
    cells.push_back({name + "_steps_mean", has ? number(measured->steps.mean, 2) : ""});
    cells.push_back({name + "_steps_max", has ? std::to_string(measured->steps.maximum) : ""});
  }
  for (const int samples : SceneBenchResult::kStillSampleCounts) {
    const auto row =
        std::find_if(r.stillFrames.begin(), r.stillFrames.end(), [&](const auto& s) { return s.samples == samples; });
    cells.push_back({"still_ms_" + std::to_string(samples) + "_samples",
                     row != r.stillFrames.end() ? number(row->milliseconds, 1) : ""});
  }
  const auto& e = r.pointError;
  cells.push_back({"point_error_count", e ? std::to_string(e->count) : ""});
  cells.push_back({"point_error_mean_px", e ? significant(e->mean) : ""});
  cells.push_back({"point_error_p99_px", e ? significant(e->p99) : ""});
  cells.push_back({"point_error_max_px", e ? significant(e->maximum) : ""});
  cells.push_back({"misjudged_hidden", e ? std::to_string(e->misjudgedHidden) : ""});
  cells.push_back({"misjudged_visible", e ? std::to_string(e->misjudgedVisible) : ""});
  for (const int factor : SceneBenchResult::kPatchDistanceFactors) {
    const auto row = std::find_if(r.patchTessellation.begin(), r.patchTessellation.end(),
                                  [&](const auto& t) { return t.distanceFactor == factor; });
    const bool has = row != r.patchTessellation.end();
    const std::string suffix = "_at_distance_x" + std::to_string(factor);
    cells.push_back({"patch_triangles" + suffix, has ? std::to_string(row->triangles) : ""});
    cells.push_back({"patch_area_p10_px" + suffix, has ? number(row->areaP10, 2) : ""});
    cells.push_back({"patch_area_p50_px" + suffix, has ? number(row->areaP50, 2) : ""});
    cells.push_back({"patch_area_p90_px" + suffix, has ? number(row->areaP90, 2) : ""});
  }
  const auto& c = r.reference;
  cells.push_back({"psnr_db", c ? number(c->psnr, 2) : ""});
  cells.push_back({"ssim", c ? number(c->ssim, 4) : ""});
  cells.push_back({"mirror_mismatch", c ? number(c->mirrorMismatch, 4) : ""});
  cells.push_back({"mismatch_estimate", c ? number(c->mismatchEstimate.share(), 4) : ""});
  cells.push_back({"mismatch_estimate_low", c ? number(c->mismatchEstimate.low, 4) : ""});
  cells.push_back({"mismatch_estimate_high", c ? number(c->mismatchEstimate.high, 4) : ""});
  cells.push_back({"estimate_ms", c ? number(c->estimateMilliseconds, 2) : ""});
  cells.push_back({"image_samples", c ? std::to_string(c->samples) : ""});
  cells.push_back({"raytrace_still_ms", c ? number(c->stillRayTraceMilliseconds, 1) : ""});
  cells.push_back({"raytrace_ms", c ? number(c->rayTraceMilliseconds, 1) : ""});
  cells.push_back({"frame_vs_raytrace", optionalNumber(r.timeVersusRayTrace(), 3)});
  return cells;
}

std::vector<ReportRow> sceneRows(std::span<const SceneBenchResult> results, std::span<const std::string> stages) {
  std::vector<ReportRow> rows;
  for (const SceneBenchResult& result : results) rows.push_back(sceneRow(result, stages));
  return rows;
}

}  // namespace

std::string formatCsv(std::span<const SceneBenchResult> results) {
  const std::vector<std::string> stages = stageNames(results);
  return csvFromRows(sceneRow(SceneBenchResult{}, stages), sceneRows(results, stages));
}

std::string formatJson(std::span<const SceneBenchResult> results) {
  return jsonFromRows("scenes", sceneRows(results, stageNames(results)));
}

std::string formatTable(std::span<const SceneBenchResult> results) {
  std::string table;
  char line[512];
  std::snprintf(line, sizeof line, "%-16s %8s %7s %6s %6s | %-17s | %-26s | %-20s | %-21s | %8s %8s\n", "scene",
                "frame ms", "fps", "first", "floor", "steps warm/cold/L", "point error mean/p99/max",
                "PSNR/SSIM/mismatch", "live estimate [95 %]", "trace ms", "x trace");
  table += line;
  for (const SceneBenchResult& r : results) {
    const auto& e = r.pointError;
    const auto& c = r.reference;
    const std::string steps = number(r.warmSteps.mean, 1) + "/" + number(r.coldSteps.mean, 1) + "/" +
                              orDash(r.coldStepsLarge ? number(r.coldStepsLarge->mean, 1) : "");
    const std::string error =
        e ? significant(e->mean) + "/" + significant(e->p99) + "/" + significant(e->maximum) : "-";
    const std::string image =
        c ? number(c->psnr, 1) + "/" + number(c->ssim, 3) + "/" + number(c->mirrorMismatch, 3) : "-";
    const std::string estimate = c ? number(c->mismatchEstimate.share(), 3) + " [" +
                                         number(c->mismatchEstimate.low, 3) + ", " +
                                         number(c->mismatchEstimate.high, 3) + "]"
                                   : "-";
    std::snprintf(line, sizeof line, "%-16.40s %8s %7s %6s %6s | %-17s | %-26s | %-20s | %-21s | %8s %8s\n",
                  r.scene.c_str(), number(r.frameMedianMilliseconds, 1).c_str(), number(r.framesPerSecond(), 1).c_str(),
                  number(r.firstFrameMilliseconds, 0).c_str(), number(r.rasterFloorMilliseconds, 1).c_str(),
                  steps.c_str(), error.c_str(), image.c_str(), estimate.c_str(),
                  orDash(c ? number(c->rayTraceMilliseconds, 0) : "").c_str(),
                  orDash(optionalNumber(r.timeVersusRayTrace(), 2)).c_str());
    table += line;
    std::string passes = "  passes (median ms):";
    for (const render::StageTiming& stage : r.stageMedians)
      passes += " " + stage.name + " " + number(stage.milliseconds, 2);
    table += passes + "\n";
    table += "  plan (last frame): " + std::to_string(r.plannedParts) + " mirror parts, " +
             std::to_string(r.rayCastParts) + " ray-cast, " + std::to_string(r.culledVertices) +
             " reflected vertices left out, " + std::to_string(r.belowBudgetVertices) + " under the error budget, " +
             std::to_string(r.uncoveredRayCast) + " uncovered pixels ray-cast, cast on " +
             std::to_string(r.castTiles.listed) + " of " + std::to_string(r.castTiles.possible) + " object tiles\n";
    if (r.searchedOverCast())
      table += "  searched / cast at " + std::to_string(r.width) + "x" + std::to_string(r.height) + ": " +
               number(*r.searchedOverCast(), 2) + " (every part searched " + number(*r.searchedFrameMilliseconds, 1) +
               " ms a frame, every part cast " + number(*r.castFrameMilliseconds, 1) +
               " ms; medians of 10 warm frames)\n";
    if (r.planner) {
      const auto& p = *r.planner;
      table += "  planner (last measured frame): searching predicted " + number(p.predicted.search, 1) + " ms, took " +
               number(p.took.search, 1) + "; ray-casting predicted " + number(p.predicted.rayCast, 1) + " ms, took " +
               number(p.took.rayCast, 1) + "; rates measured here over the llvmpipe fit: searching " +
               number(p.rates.search, 2) + ", ray-casting " + number(p.rates.rayCast, 2) + "\n";
    }
    if (!r.stillFrames.empty()) {
      std::string still = "  still frames (last pose, samples a pixel: ms):";
      for (const SceneBenchResult::StillFrame& s : r.stillFrames)
        still += " " + std::to_string(s.samples) + ": " + number(s.milliseconds, 1) + ";";
      if (c)
        still += " images compared at " + std::to_string(c->samples) + " samples with a " + std::to_string(c->samples) +
                 "-ray trace (" + number(c->stillRayTraceMilliseconds, 0) + " ms);";
      still.back() = '\n';
      table += still;
    }
    if (!r.patchTessellation.empty()) {
      std::string patches = "  patch tessellation (last pose, camera distance ×):";
      for (const SceneBenchResult::PatchTessellation& t : r.patchTessellation)
        patches += " " + std::to_string(t.distanceFactor) + ": " + std::to_string(t.triangles) +
                   " triangles, pixel area " + number(t.areaP10, 1) + "/" + number(t.areaP50, 1) + "/" +
                   number(t.areaP90, 1) + ";";
      patches.back() = '\n';
      table += patches;
    }
    if (r.searches.empty()) continue;
    std::string searches = "  searches (first frames, warm):";
    for (const SceneBenchResult::SearchComparison& s : r.searches) {
      searches += std::string(" ") + passes::searchStrategyName(s.strategy) + " " + number(s.milliseconds, 2) +
                  " ms, " + number(s.steps.mean, 1) + " steps (max " + std::to_string(s.steps.maximum) + ")";
      if (s.strategy == passes::SearchStrategy::Hierarchy)
        searches += ", " + std::to_string(s.enlarged) + " enlarged, " + std::to_string(s.inNoCone) + " in no cone";
      searches += ";";
    }
    searches.back() = '\n';
    table += searches;
  }
  return table;
}

}  // namespace specula::bench
