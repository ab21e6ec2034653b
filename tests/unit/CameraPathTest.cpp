// specula-path's keyframe parsing and interpolation.
#include <gtest/gtest.h>

#include "CameraPath.h"

namespace specula::client {
namespace {

TEST(CameraPath, InterpolatesLinearlyAndClampsOutsideTheKeys) {
  auto path = parseCameraPathJson(R"({"keys": [
      {"time": 0, "eye": [0, 1, 5], "target": [0, 0, 0], "fov": 40, "scene_time": 0},
      {"time": 2, "eye": [4, 1, 5], "target": [0, 2, 0], "fov": 60, "scene_time": 10}]})");
  ASSERT_TRUE(path) << path.error();
  EXPECT_DOUBLE_EQ(path->duration(), 2.0);
  const PathKey middle = path->at(0.5);
  EXPECT_FLOAT_EQ(middle.eye.x, 1.0f);
  EXPECT_FLOAT_EQ(middle.target.y, 0.5f);
  EXPECT_FLOAT_EQ(middle.fovDegrees, 45.0f);
  EXPECT_DOUBLE_EQ(*middle.sceneTime, 2.5);
  EXPECT_FLOAT_EQ(path->at(-1.0).eye.x, 0.0f);
  EXPECT_FLOAT_EQ(path->at(9.0).eye.x, 4.0f);
}

TEST(CameraPath, ReadsCsvWithOptionalColumnsInAnyOrder) {
  auto path =
      parseCameraPathCsv("target_x,target_y,target_z,time,eye_x,eye_y,eye_z,fov\n0,0,0,0,0,1,5,30\n0,0,0,1,2,1,5,50\n");
  ASSERT_TRUE(path) << path.error();
  ASSERT_EQ(path->keys.size(), 2u);
  EXPECT_FLOAT_EQ(path->at(0.5).eye.x, 1.0f);
  EXPECT_FLOAT_EQ(path->at(0.5).fovDegrees, 40.0f);
  EXPECT_FALSE(path->keys[0].sceneTime.has_value());
  EXPECT_FLOAT_EQ(path->keys[0].up.y, 1.0f) << "up defaults to +y";
}

TEST(CameraPath, RejectsBadPathsNamingTheProblem) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({"keys": []})", "no keys"},
      {R"({"keys": [{"eye": [0,1,5], "target": [0,0,0]}]})", "numeric \"time\""},
      {R"({"keys": [{"time": 0, "eye": [0,1], "target": [0,0,0]}]})", "\"eye\" must be [x, y, z]"},
      {R"({"keys": [{"time": 0, "eye": [0,0,0], "target": [0,0,0]}]})", "eye and target coincide"},
      {R"({"keys": [{"time": 1, "eye": [0,1,5], "target": [0,0,0]}, {"time": 1, "eye": [0,1,5], "target": [0,0,0]}]})",
       "increase strictly"},
      {R"({"keys": [{"time": 0, "eye": [0,1,5], "target": [0,0,0], "fov": 180}]})", "fov must be in (0, 180)"},
      {R"({"keys": [{"time": 0, "eye": [0,1,5], "target": [0,0,0], "scene_time": 1}, {"time": 1, "eye": [0,1,5], "target": [0,0,0]}]})",
       "on every key or on none"},
      {"[1, 2]", "an object with a \"keys\" array"},
  };
  for (const auto& [text, expected] : bad) {
    auto path = parseCameraPathJson(text);
    ASSERT_FALSE(path) << text;
    EXPECT_NE(path.error().find(expected), std::string::npos) << path.error();
  }
  auto csv = parseCameraPathCsv("time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n0,1,2,abc,0,0,0\n");
  ASSERT_FALSE(csv);
  EXPECT_NE(csv.error().find("line 2: 'abc' is not a number"), std::string::npos) << csv.error();
  EXPECT_FALSE(loadCameraPath("/nonexistent/path.json"));
  EXPECT_NE(loadCameraPath("path.txt").error().find(".json or .csv"), std::string::npos);
}

}  // namespace
}  // namespace specula::client
