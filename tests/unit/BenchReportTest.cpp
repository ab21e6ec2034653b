// CSV and JSON of `specula bench`: one column set for every row, empty/null where not measured,
// and scene names from user files escaped so they cannot break either format.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "bench/AccuracyBenchmark.h"
#include "bench/AccuracyReport.h"
#include "bench/SceneReport.h"
#include "scene/builtin/BuiltinScenes.h"

using namespace specula;

namespace {

bench::SceneBenchResult measured(const std::string& name) {
  bench::SceneBenchResult r;
  r.scene = name;
  r.width = 640;
  r.height = 480;
  r.frames = 2;
  r.frameMedianMilliseconds = 20.0;
  r.rasterFloorMilliseconds = 7.25;
  r.stageMedians = {{"scene", 5.0}, {"search", 2.5}};
  r.warmSteps = {1.5, 4, 100};
  r.coldSteps = {16.0, 22, 100};
  r.pointError = bench::SceneBenchResult::PointError{10, 0.01, 0.5, 1.25, 1, 0};
  r.reference = bench::SceneBenchResult::ReferenceComparison{
      20.5, 0.95, 0.1, 4, 44.0, 170.0, reference::wilsonInterval(26, 256), 3.5};
  r.stillFrames = {{1, 21.0}, {4, 80.5}, {8, 161.0}};
  return r;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::stringstream stream(text);
  for (std::string line; std::getline(stream, line);) result.push_back(line);
  return result;
}

}  // namespace

TEST(BenchReport, CsvHasOneColumnSetAndEmptyCellsWhereNothingWasMeasured) {
  bench::SceneBenchResult plain = measured("plain");
  plain.pointError.reset();
  plain.reference.reset();
  plain.stageMedians = {{"scene", 4.0}};  // no mirror visible: no search pass
  const std::vector<bench::SceneBenchResult> results = {measured("sphere"), plain};
  const auto rows = lines(bench::formatCsv(results));
  ASSERT_EQ(rows.size(), 3u);
  const auto commas = [](const std::string& row) { return std::count(row.begin(), row.end(), ','); };
  EXPECT_EQ(commas(rows[1]), commas(rows[0]));
  EXPECT_EQ(commas(rows[2]), commas(rows[0]));
  EXPECT_NE(rows[0].find(",scene_ms,search_ms,"), std::string::npos);
  EXPECT_NE(rows[0].find(",fps,raster_floor_ms,"), std::string::npos);
  EXPECT_NE(rows[1].find(",50.0,7.25,"), std::string::npos) << "fps = 1000 / 20 ms, then the floor: " << rows[1];
  EXPECT_NE(rows[1].find(",0.5,1.25,"), std::string::npos) << rows[1];
  EXPECT_EQ(rows[2].substr(rows[2].size() - 11), ",,,,,,,,,,,") << "no reference: eleven empty cells at the end";
  // 26 of 256 sampled mirror pixels wrong: 0.1016, Wilson's 95 % interval [0.0703, 0.1447], traced in 3.5 ms.
  EXPECT_NE(
      rows[0].find(",mirror_mismatch,mismatch_estimate,mismatch_estimate_low,mismatch_estimate_high,estimate_ms,"),
      std::string::npos)
      << rows[0];
  EXPECT_NE(rows[1].find(",0.1000,0.1016,0.0703,0.1447,3.50,"), std::string::npos) << rows[1];
}

TEST(BenchReport, FrameTimeIsAlsoGivenAsAMultipleOfTheRayTracers) {
  const std::vector<bench::SceneBenchResult> results = {measured("sphere")};  // 20 ms against 44 ms
  ASSERT_TRUE(results[0].timeVersusRayTrace());
  EXPECT_NEAR(*results[0].timeVersusRayTrace(), 20.0 / 44.0, 1e-12);
  const auto csv = lines(bench::formatCsv(results));
  EXPECT_NE(csv[0].find(",raytrace_ms,frame_vs_raytrace"), std::string::npos) << csv[0];
  EXPECT_EQ(csv[1].substr(csv[1].size() - 6), ",0.455") << csv[1];
  const auto table = lines(bench::formatTable(results));
  EXPECT_NE(table[0].find("x trace"), std::string::npos) << table[0];
  EXPECT_NE(table[0].find(" floor "), std::string::npos) << table[0];
  EXPECT_NE(table[1].find(" 7.2 "), std::string::npos) << "the raster floor: " << table[1];
  EXPECT_NE(table[1].find(" 0.45"), std::string::npos) << table[1];
}

TEST(BenchReport, StillFramesShowWhatAntiAliasingCosts) {
  const std::vector<bench::SceneBenchResult> results = {measured("sphere")};
  const auto csv = lines(bench::formatCsv(results));
  EXPECT_NE(csv[0].find(",still_ms_1_samples,still_ms_4_samples,still_ms_8_samples,"), std::string::npos) << csv[0];
  EXPECT_NE(csv[1].find(",21.0,80.5,161.0,"), std::string::npos) << csv[1];
  EXPECT_NE(csv[0].find(",image_samples,raytrace_still_ms,raytrace_ms,"), std::string::npos) << csv[0];
  EXPECT_NE(csv[1].find(",4,170.0,44.0,"), std::string::npos) << csv[1];
  const std::string table = bench::formatTable(results);
  EXPECT_NE(
      table.find(
          "still frames (last pose, samples a pixel: ms): 1: 21.0; 4: 80.5; 8: 161.0; images compared at 4 samples "
          "with a 4-ray trace (170 ms)\n"),
      std::string::npos)
      << table;
}

TEST(BenchReport, JsonWritesNullForMissingValuesAndEscapesNames) {
  bench::SceneBenchResult odd = measured("my \"odd\"\\scene\n");
  odd.reference.reset();
  const std::string json = bench::formatJson(std::vector<bench::SceneBenchResult>{odd});
  EXPECT_NE(json.find(R"("scene": "my \"odd\"\\scene\n")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("psnr_db": null)"), std::string::npos);
  EXPECT_NE(json.find(R"("point_error_max_px": 1.25)"), std::string::npos);
  EXPECT_EQ(json.substr(0, 12), R"({"scenes": [)");
}

TEST(BenchReport, CsvQuotesNamesWithCommasOrQuotes) {
  const auto rows = lines(bench::formatCsv(std::vector<bench::SceneBenchResult>{measured("a,\"b\"")}));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].rfind(R"("a,""b""",)", 0), 0u) << rows[1];
}

TEST(BenchReport, TableShowsDashesWhereNothingWasMeasured) {
  bench::SceneBenchResult plain = measured("plain");
  plain.pointError.reset();
  const std::string table = bench::formatTable(std::vector<bench::SceneBenchResult>{plain});
  EXPECT_NE(table.find("plain"), std::string::npos);
  EXPECT_NE(table.find("| -  "), std::string::npos) << table;
  EXPECT_NE(table.find("passes (median ms): scene 5.00 search 2.50"), std::string::npos) << table;
}

namespace {

bench::AccuracyRow accuracy(const std::string& setting, double milliseconds, double mismatch) {
  bench::AccuracyRow row{"scene", setting, "search"};
  row.frameMilliseconds = milliseconds;
  row.mirrorMismatch = mismatch;
  return row;
}

bool onFront(const std::vector<bench::AccuracyRow>& rows, const std::string& setting) {
  return std::find_if(rows.begin(), rows.end(), [&](const auto& row) { return row.setting == setting; })->pareto;
}

}  // namespace

TEST(AccuracyReport, TheParetoFrontHoldsExactlyTheUndominatedSettings) {
  bench::AccuracyRow reference = accuracy("reference", 1.0, 0.0);  // fastest and exact, yet not a setting
  reference.reference = true;
  std::vector<bench::AccuracyRow> rows = {reference,
                                          accuracy("fast coarse", 10.0, 0.2),
                                          accuracy("slow fine", 100.0, 0.01),
                                          accuracy("middle", 30.0, 0.05),
                                          accuracy("dominated", 40.0, 0.06),        // middle is faster and finer
                                          accuracy("tie in time", 30.0, 0.07),      // as fast as middle, coarser
                                          accuracy("same as middle", 30.0, 0.05)};  // equal: neither dominates
  bench::markParetoFront(rows);
  EXPECT_FALSE(onFront(rows, "reference"));
  EXPECT_TRUE(onFront(rows, "fast coarse"));
  EXPECT_TRUE(onFront(rows, "slow fine"));
  EXPECT_TRUE(onFront(rows, "middle"));
  EXPECT_TRUE(onFront(rows, "same as middle"));
  EXPECT_FALSE(onFront(rows, "dominated"));
  EXPECT_FALSE(onFront(rows, "tie in time"));
}

TEST(AccuracyReport, CsvMarkdownAndPlotCarryEverySettingAndMarkTheFront) {
  bench::AccuracyRow reference = accuracy("ray-traced reference", 250.0, 0.0);
  reference.reference = true;
  bench::AccuracyRow search = accuracy("search, no tessellation", 12.5, 0.125);
  search.pointErrorP99 = 0.004;
  search.pointErrorMax = 0.25;
  search.reflectionVertices = 1536;
  std::vector<bench::AccuracyRow> rows = {reference, search, accuracy("full level 4", 80.0, 0.0)};
  bench::markParetoFront(rows);

  const auto csv = lines(bench::formatAccuracyCsv(rows));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0].rfind("scene,setting,family,frame_ms_median,", 0), 0u) << csv[0];
  EXPECT_NE(csv[2].find(R"("search, no tessellation",search,12.50,)"), std::string::npos) << csv[2];
  EXPECT_NE(csv[2].find(",0.004,0.25,1536,"), std::string::npos) << csv[2];
  EXPECT_EQ(csv[1].substr(csv[1].size() - 6), ",false") << "the reference is never on the front";

  const std::string markdown = bench::formatAccuracyMarkdown(rows, "### scene");
  EXPECT_NE(markdown.find("| **search, no tessellation** | 12.5 |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| ray-traced reference | 250.0 |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| 0.004 / 0.25 |"), std::string::npos) << markdown;

  const std::string plot = bench::accuracyPlotScript(rows, "a \"quoted\" title", "out.png", "out.svg");
  EXPECT_NE(plot.find(R"(set title "a \"quoted\" title")"), std::string::npos) << plot;
  EXPECT_NE(plot.find(R"("search, no tessellation")"), std::string::npos);
  EXPECT_NE(plot.find("title 'Pareto front'"), std::string::npos);
  EXPECT_NE(plot.find("set arrow 1 from 250.000, graph 0"), std::string::npos)
      << "the reference's time as a vertical line";
  EXPECT_NE(plot.find("set output \"out.png\""), std::string::npos);
  EXPECT_NE(plot.find("set output \"out.svg\""), std::string::npos);
  // The exact setting sits on the floor of the log axis instead of vanishing at 0.
  EXPECT_NE(plot.find("80.000 0.000100 "), std::string::npos) << plot;
  const std::string frontBlock = plot.substr(plot.find("$front << EOD"));
  EXPECT_LT(frontBlock.find("12.500 "), frontBlock.find("80.000 ")) << "the front is drawn in order of time";
}

TEST(AccuracyReport, CrowdedSettingsGetLabelsThatDoNotOverlap) {
  std::vector<bench::AccuracyRow> rows;
  for (int i = 0; i < 12; ++i)
    rows.push_back(accuracy("same " + std::to_string(i), 100.0, 0.0218));  // identical points
  for (int i = 0; i < 6; ++i)
    rows.push_back(accuracy("near " + std::to_string(i), 100.0 + i, 0.0218 * (1.0 + 0.01 * i)));
  bench::markParetoFront(rows);
  const std::string plot = bench::accuracyPlotScript(rows, "crowded", "a.png", "a.svg");
  const std::string block = plot.substr(plot.find("$settings << EOD\n") + 17,
                                        plot.find("EOD\n$front") - plot.find("$settings << EOD\n") - 17);
  std::vector<double> heights;
  for (const std::string& line : lines(block)) {
    std::stringstream fields(line);
    double time = 0.0, mismatch = 0.0, labelHeight = 0.0;
    fields >> time >> mismatch >> labelHeight;
    heights.push_back(std::log10(labelHeight));
  }
  ASSERT_EQ(heights.size(), rows.size());
  std::sort(heights.begin(), heights.end());
  for (std::size_t i = 1; i < heights.size(); ++i)
    EXPECT_GT(heights[i] - heights[i - 1], 0.02) << "labels " << i - 1 << " and " << i;
}

TEST(AccuracySweep, MeshMirrorsApproximatingAnExactShapeGetMeshResolutionRows) {
  const scene::Scene exact = *scene::makeBuiltinScene("checker-sphere");
  const scene::Scene mesh = *scene::makeBuiltinScene("mesh-sphere");
  const auto meshRows = [](const std::vector<bench::AccuracySetting>& sweep) {
    return std::count_if(sweep.begin(), sweep.end(), [](const auto& s) { return s.mirrorMesh.has_value(); });
  };
  EXPECT_EQ(meshRows(bench::accuracySweep(exact)), 0) << "the exact sphere has no mesh to vary";
  EXPECT_EQ(meshRows(bench::accuracySweep(mesh)), 4);
  for (const scene::Scene* scene : {&exact, &mesh}) {
    const auto sweep = bench::accuracySweep(*scene);
    EXPECT_EQ(std::count_if(sweep.begin(), sweep.end(),
                            [](const auto& s) { return s.settings.search == passes::SearchStrategy::Hierarchy; }),
              2)
        << "both searches side by side, with and without tessellation";
    EXPECT_EQ(std::count_if(sweep.begin(), sweep.end(),
                            [](const auto& s) {
                              return s.settings.search == passes::SearchStrategy::ExplosionMap &&
                                     s.settings.virtualPixels == passes::VirtualPixels::AsPlaced &&
                                     !s.settings.explosionRefine && !s.settings.explosionMirrorPlacement;
                            }),
              3)
        << "the paper's explosion map at three map sizes";
    EXPECT_EQ(std::count_if(sweep.begin(), sweep.end(), [](const auto& s) { return s.settings.explosionRefine; }), 1);
    EXPECT_EQ(
        std::count_if(sweep.begin(), sweep.end(), [](const auto& s) { return s.settings.explosionMirrorPlacement; }), 1)
        << "and once with the paper's placement";
  }
  // The re-meshed sphere lies on the exact shape, with its normals.
  const scene::Scene coarse = bench::withMirrorMeshes(mesh, {32, 16});
  const scene::SceneObject& mirror = coarse.objects[0];
  ASSERT_TRUE(mirror.mirror);
  const scene::Mesh& sphere = coarse.meshes[mirror.mesh];
  EXPECT_EQ(sphere.triangleCount(), 2u * 32 * (16 - 1));  // one triangle per slice at each pole, two elsewhere
  for (const scene::Vertex& v : sphere.vertices) {
    EXPECT_NEAR(glm::length(v.position - mirror.mirror->analytic->center), mirror.mirror->analytic->radii.x, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::normalize(v.position)), 1.0f, 1e-5f);
  }
  EXPECT_EQ(coarse.meshes[coarse.objects[1].mesh].name, mesh.meshes[mesh.objects[1].mesh].name)
      << "other objects keep their meshes";
}

TEST(BenchReport, PatchTessellationAtEachDistanceHasItsColumnsAndLine) {
  bench::SceneBenchResult teapot = measured("teapot");
  teapot.patchTessellation = {{1, 14137, 1.2, 6.5, 24.1}, {2, 4074, 0.9, 4.8, 23.4}, {4, 1520, 0.4, 2.7, 14.5}};
  const std::vector<bench::SceneBenchResult> results = {teapot, measured("plain")};
  const auto csv = lines(bench::formatCsv(results));
  EXPECT_NE(csv[0].find(",patch_triangles_at_distance_x1,patch_area_p10_px_at_distance_x1,"), std::string::npos)
      << csv[0];
  EXPECT_NE(csv[1].find(",14137,1.20,6.50,24.10,4074,0.90,4.80,23.40,1520,0.40,2.70,14.50,"), std::string::npos)
      << csv[1];
  EXPECT_NE(csv[2].find(",0" + std::string(13, ',') + "20.50,"), std::string::npos)
      << "no patches: twelve empty cells between the point errors and the reference " << csv[2];
  const std::string table = bench::formatTable(results);
  EXPECT_NE(
      table.find("patch tessellation (last pose, camera distance ×): 1: 14137 triangles, pixel area 1.2/6.5/24.1;"),
      std::string::npos)
      << table;
  EXPECT_EQ(table.find("patch tessellation", table.find("plain")), std::string::npos) << "no line without patches";
}
