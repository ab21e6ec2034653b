#include <gtest/gtest.h>

#include "math/Camera.h"
#include "math/Color.h"

using namespace specula::math;

TEST(Camera, DefaultCameraHasNoProblem) { EXPECT_FALSE(cameraProblem(Camera{}).has_value()); }

TEST(Camera, RejectsEyeOnTargetParallelUpAndBadFov) {
  EXPECT_TRUE(cameraProblem(Camera{{1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 40}).has_value());
  EXPECT_TRUE(cameraProblem(Camera{{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 40}).has_value());
  EXPECT_TRUE(cameraProblem(Camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 180}).has_value());
  EXPECT_TRUE(
      cameraProblem(Camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, std::numeric_limits<float>::quiet_NaN()}).has_value());
}

TEST(Camera, ViewMatrixPutsTargetOnNegativeZAxis) {
  const Camera camera{{1, 3, 3.5f}, {0, -0.3f, 0}, {0, 1, 0}, 40};
  const glm::vec4 t = viewMatrix(camera) * glm::vec4(camera.target, 1.0f);
  EXPECT_NEAR(t.x, 0.0f, 1e-5f);
  EXPECT_NEAR(t.y, 0.0f, 1e-5f);
  EXPECT_NEAR(t.z, -glm::length(camera.target - camera.eye), 1e-5f);
}

TEST(Color, SrgbRoundTripsEveryByte) {
  for (int byte = 0; byte < 256; ++byte) {
    const float linear = srgbToLinear(static_cast<float>(byte) / 255.0f);
    EXPECT_EQ(static_cast<int>(std::lround(linearToSrgb(linear) * 255.0f)), byte);
  }
}
