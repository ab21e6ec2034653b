// CSV and JSON of `specula bench`: one column set for every row, empty/null where not measured,
// and scene names from user files escaped so they cannot break either format.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "bench/BenchReport.h"

using namespace specula;

namespace {

bench::SceneBenchResult measured(const std::string& name) {
  bench::SceneBenchResult r;
  r.scene = name;
  r.width = 640;
  r.height = 480;
  r.frames = 2;
  r.frameMedianMilliseconds = 20.0;
  r.stageMedians = {{"scene", 5.0}, {"search", 2.5}};
  r.warmSteps = {1.5, 4, 100};
  r.coldSteps = {16.0, 22, 100};
  r.pointError = bench::SceneBenchResult::PointError{10, 0.01, 0.5, 1.25, 1, 0};
  r.reference = bench::SceneBenchResult::ReferenceComparison{20.5, 0.95, 0.1, 44.0};
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
  EXPECT_NE(rows[0].find(",fps,"), std::string::npos);
  EXPECT_NE(rows[1].find(",50.0,"), std::string::npos) << "fps = 1000 / 20 ms: " << rows[1];
  EXPECT_NE(rows[1].find(",0.5,1.25,"), std::string::npos) << rows[1];
  EXPECT_EQ(rows[2].substr(rows[2].size() - 4), ",,,,") << "no reference: four empty cells at the end";
}

TEST(BenchReport, JsonWritesNullForMissingValuesAndEscapesNames) {
  bench::SceneBenchResult odd = measured("my \"odd\"\\scene\n");
  odd.reference.reset();
  const std::string json = bench::formatJson(std::vector<bench::SceneBenchResult>{odd});
  EXPECT_NE(json.find(R"("scene": "my \"odd\"\\scene\u000a")"), std::string::npos) << json;
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
