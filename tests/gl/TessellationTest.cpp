// Adaptive tessellation (shaders/tessellation) against its own bounds and, for images, the Embree
// reference: counts follow the level rule, crack-free mode leaves no holes, and error falls with
// the threshold.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "gl/GlContext.h"
#include "reference/ImageMetrics.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"
#include "SceneRig.h"

using namespace specula;
using passes::TessellationMetric;
using passes::TessellationMode;

namespace {

// A scene's renderer with the pose every test here measures: the scene at time 0.
struct Rig : specula::testing::Rig {
  scene::ScenePose pose;
};

Rig makeRig(const std::string& sceneName) {
  Rig rig{specula::testing::makeRig(sceneName), {}};
  if (rig.renderer) rig.pose = scene::ScenePose::at(rig.renderer->scene(), 0.0);
  return rig;
}

// The ray tracer's frame at the rig's pose.
std::optional<reference::ReferenceImage> referenceImage(const Rig& rig, int width, int height) {
  auto tracer = reference::RayTracer::create(std::make_shared<const scene::Scene>(rig.renderer->scene()));
  EXPECT_TRUE(tracer) << tracer.error();
  if (!tracer) return std::nullopt;
  auto truth = (*tracer)->render(rig.pose, {width, height, 1, 0});
  EXPECT_TRUE(truth) << truth.error();
  if (!truth) return std::nullopt;
  return std::move(truth.value());
}

passes::ReflectionSettings tessellation(TessellationMode mode, TessellationMetric metric, float threshold, int level) {
  passes::ReflectionSettings settings;
  settings.tessellation = {mode, metric, threshold, level};
  return settings;
}

render::RenderedFrame renderFrame(Rig& rig, const passes::ReflectionSettings& settings, int width = 320,
                                  int height = 240) {
  auto frame = rig.renderer->render(rig.pose, width, height, specula::testing::virtualObjects(settings));
  EXPECT_TRUE(frame) << frame.error();
  return frame ? std::move(frame.value()) : render::RenderedFrame{};
}

std::uint64_t power4(int level) { return std::uint64_t{1} << (2 * level); }

// The reference's colour of the mirror reflecting nothing: the commonest colour inside the mirror
// of a scene that mostly reflects the sky.
std::array<int, 3> backgroundInMirror(const std::vector<std::uint8_t>& rgba, const std::vector<std::uint8_t>& mask) {
  std::map<std::array<int, 3>, int> counts;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) ++counts[{rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]}];
  return std::max_element(counts.begin(), counts.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
}

// Mirror pixels (not on the mirror's outline) where the reference shows the plane and we show
// the background reflection: holes in the virtual geometry.
int holesInReflection(const std::vector<std::uint8_t>& ours, const reference::ReferenceImage& truth, int width,
                      int height) {
  const std::array<int, 3> background = backgroundInMirror(truth.rgba, truth.mirrorMask);
  const auto isBackground = [&](const std::vector<std::uint8_t>& rgba, std::size_t i) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(rgba[4 * i + c] - background[c]) > 3) return false;
    return true;
  };
  int holes = 0;
  for (int y = 1; y + 1 < height; ++y) {
    for (int x = 1; x + 1 < width; ++x) {
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) interior = interior && truth.mirrorMask[(y + dy) * width + x + dx];
      const std::size_t i = static_cast<std::size_t>(y * width + x);
      if (interior && !isBackground(truth.rgba, i) && isBackground(ours, i)) ++holes;
    }
  }
  return holes;
}

}  // namespace

TEST(Tessellation, ThresholdZeroGivesExactlyFullTessellation) {
  Rig rig = makeRig("quad");  // both quad triangles are drawn: every one of them splits
  ASSERT_TRUE(rig.renderer);
  for (TessellationMode mode : {TessellationMode::Paper, TessellationMode::CrackFree}) {
    for (TessellationMetric metric : {TessellationMetric::Angle, TessellationMetric::Pixels}) {
      for (int level = 1; level <= 4; ++level) {
        const auto frame = renderFrame(rig, tessellation(mode, metric, 0.0f, level));
        const passes::TessellationStatistics& t = frame.tessellation;
        ASSERT_EQ(t.inputTriangles, 2u);
        ASSERT_EQ(t.trianglesPerRound.size(), static_cast<std::size_t>(level + 1));
        for (int round = 0; round <= level; ++round)
          EXPECT_EQ(t.trianglesPerRound[round], 2u * power4(round)) << "round " << round;
        EXPECT_EQ(t.finishedTriangles, 2u * power4(level)) << "level " << level;
        EXPECT_FALSE(t.capped);
      }
    }
  }
}

TEST(Tessellation, AngleThresholdOneTessellatesNothing) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  for (TessellationMode mode : {TessellationMode::Paper, TessellationMode::CrackFree}) {
    const auto frame = renderFrame(rig, tessellation(mode, TessellationMetric::Angle, 1.0f, 4));
    EXPECT_GT(frame.tessellation.inputTriangles, 100u);
    EXPECT_EQ(frame.tessellation.finishedTriangles, frame.tessellation.inputTriangles);
    EXPECT_EQ(frame.tessellation.trianglesPerRound.size(), 1u);
    EXPECT_EQ(frame.tessellation.midpointSearches.searched, 0u);
  }
}

TEST(Tessellation, CountsNeverExceedTheLevelBoundAndFollowSettingsChangedAtRunTime) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  std::map<std::uint32_t, int> distinctCounts;
  for (TessellationMode mode : {TessellationMode::Paper, TessellationMode::CrackFree}) {
    for (auto [metric, threshold] :
         {std::pair{TessellationMetric::Angle, 0.01f}, std::pair{TessellationMetric::Angle, 0.001f},
          std::pair{TessellationMetric::Pixels, 2.0f}, std::pair{TessellationMetric::Pixels, 0.5f}}) {
      for (int level : {1, 3}) {
        const auto frame = renderFrame(rig, tessellation(mode, metric, threshold, level));
        const passes::TessellationStatistics& t = frame.tessellation;
        ASSERT_LE(t.trianglesPerRound.size(), static_cast<std::size_t>(level + 1));
        for (std::size_t round = 0; round < t.trianglesPerRound.size(); ++round)
          EXPECT_LE(t.trianglesPerRound[round], t.inputTriangles * power4(static_cast<int>(round)));
        EXPECT_LE(t.finishedTriangles, t.inputTriangles * power4(level));
        EXPECT_GE(t.finishedTriangles, t.inputTriangles);
        ++distinctCounts[t.finishedTriangles];
      }
    }
  }
  EXPECT_GE(distinctCounts.size(), 8u) << "threshold, level and mode must change the result from frame to frame";
}

TEST(Tessellation, NeitherModeLeavesMoreThanATraceOfHolesInACoarsePlanesReflection) {
  Rig rig = makeRig("quad");
  ASSERT_TRUE(rig.renderer);
  constexpr int kWidth = 640, kHeight = 480;
  const auto truth = referenceImage(rig, kWidth, kHeight);
  ASSERT_TRUE(truth);
  std::map<std::string, int> holes;
  for (auto [name, mode] :
       {std::pair{"paper", TessellationMode::Paper}, std::pair{"crack-free", TessellationMode::CrackFree}}) {
    const auto frame = renderFrame(rig, tessellation(mode, TessellationMetric::Pixels, 1.0f, 5), kWidth, kHeight);
    holes[name] = holesInReflection(frame.rgba, *truth, kWidth, kHeight);
  }
  // Szabo's loop splits neighbours differently and opened T-junction holes here (62 px measured)
  // while virtual triangles were drawn as they lie; dilated by 2 px and kept only where each pixel's
  // reflected ray meets the triangle itself, neither mode leaves more than a trace (measured: paper
  // 0, crack-free 11 px along one edge whose image bends between its searched midpoints; 1 at 0.5 px).
  const std::size_t mirrorPixels =
      static_cast<std::size_t>(std::count(truth->mirrorMask.begin(), truth->mirrorMask.end(), 1));
  std::printf("holes in the reflection: paper %d, crack-free %d of %zu mirror pixels\n", holes["paper"],
              holes["crack-free"], mirrorPixels);
  EXPECT_LE(holes["paper"], static_cast<int>(mirrorPixels / 2000));
  EXPECT_LE(holes["crack-free"], static_cast<int>(mirrorPixels / 2000));
}

TEST(Tessellation, CheckerSphereMismatchFallsAsTheThresholdFalls) {
  Rig rig = makeRig("checker-sphere");
  ASSERT_TRUE(rig.renderer);
  constexpr int kWidth = 640, kHeight = 480;
  const auto truth = referenceImage(rig, kWidth, kHeight);
  ASSERT_TRUE(truth);
  std::vector<double> mismatch;
  std::vector<passes::ReflectionSettings> settings = {
      tessellation(TessellationMode::None, TessellationMetric::Pixels, 1.0f, 0)};
  for (float threshold : {4.0f, 1.0f, 0.25f})
    settings.push_back(tessellation(TessellationMode::CrackFree, TessellationMetric::Pixels, threshold, 5));
  for (const passes::ReflectionSettings& setting : settings) {
    mismatch.push_back(specula::testing::mismatchAgainst(*truth, renderFrame(rig, setting, kWidth, kHeight)).share);
  }
  // Measured: 0.069 untessellated, then 0.044, 0.023, 0.008 at 4, 1 and 0.25 px.
  for (std::size_t i = 1; i < mismatch.size(); ++i) EXPECT_LT(mismatch[i], mismatch[i - 1]) << "threshold step " << i;
  EXPECT_LT(mismatch.back(), 0.5 * mismatch.front());
}

// The round's decision is split into a classification of every triangle, a search of only the
// edges it lists and a decision per triangle. On the scenes of these tests it splits exactly what
// the single split kernel it replaced did (rounds and searches measured at 640x480 on the second
// frame at time 0 with the default settings, before the change, on llvmpipe). It finishes fewer: the
// single kernel also emitted triangles no virtual triangle could be drawn from (a corner unreflected
// or every corner hidden), 243, 1496 and 27034 then; those are now left out before emission.
// Another driver rounds differently (NVIDIA's fused multiply-adds): an edge whose error lies within
// rounding of the threshold splits there and not here, and the difference grows with each round
// (measured on an H200: checker-sphere 1332 finished, 5147 searches, last round 169 of 182). There
// the counts must agree to 2 % overall and 10 % per round, the same deterministic frame every time.
TEST(Tessellation, ClassifyingThenSearchingSplitsWhatTheSingleKernelDid) {
  struct Expected {
    const char* scene;
    std::uint32_t inputTriangles, drawableFinishedTriangles, midpointSearches;
    std::vector<std::uint32_t> trianglesPerRound;
  };
  for (const Expected& expected : {Expected{"quad", 2, 233, 414, {2, 8, 32, 106, 206}},
                                   Expected{"checker-sphere", 512, 1340, 5139, {512, 520, 514, 340, 182}},
                                   Expected{"teapot-table", 26500, 26999, 4159, {26500, 136, 149, 230, 277}}}) {
    Rig rig = makeRig(expected.scene);
    ASSERT_TRUE(rig.renderer);
    const bool measuredDriver = rig.context->info().renderer.find("llvmpipe") != std::string::npos;
    const auto expectCount = [&](std::uint32_t actual, std::uint32_t wanted, double tolerance,
                                 const std::string& what) {
      if (measuredDriver) {
        EXPECT_EQ(actual, wanted) << expected.scene << ": " << what;
      } else {
        EXPECT_NEAR(actual, wanted, tolerance * wanted)
            << expected.scene << ": " << what << " on " << rig.context->info().renderer;
      }
    };
    renderFrame(rig, {}, 640, 480);
    const render::RenderedFrame frame = renderFrame(rig, {}, 640, 480);
    const passes::TessellationStatistics& statistics = frame.tessellation;
    EXPECT_EQ(statistics.inputTriangles, expected.inputTriangles) << expected.scene;
    expectCount(statistics.finishedTriangles, expected.drawableFinishedTriangles, 0.02, "finished triangles");
    expectCount(statistics.midpointSearches.searched, expected.midpointSearches, 0.02, "midpoint searches");
    ASSERT_EQ(statistics.trianglesPerRound.size(), expected.trianglesPerRound.size()) << expected.scene;
    for (std::size_t round = 0; round < expected.trianglesPerRound.size(); ++round)
      expectCount(statistics.trianglesPerRound[round], expected.trianglesPerRound[round], 0.10,
                  "round " + std::to_string(round));
    const render::RenderedFrame again = renderFrame(rig, {}, 640, 480);
    EXPECT_EQ(again.tessellation.trianglesPerRound, statistics.trianglesPerRound)
        << expected.scene << ": the same frame splits the same";
  }
}

// Full tessellation of the kitchen at level 3 would make about 2·10^6 triangles, past the finished
// list's cap. Each mirror part may fill only its share of what is left, so the bowl's two parts both
// stop at level 2 and the frame equals level 2's. Before, the first part filled the list, the second
// part's round was dropped and the capped frame showed holes (mismatch 0.086 at 640x480 against level
// 2's 0.041; `specula bench tessellation`).
TEST(Tessellation, AFrameCappedPartWayStillDrawsEveryPart) {
  Rig rig = makeRig("kitchen");
  ASSERT_TRUE(rig.renderer);
  constexpr int kWidth = 320, kHeight = 240;
  const auto truth = referenceImage(rig, kWidth, kHeight);
  ASSERT_TRUE(truth);
  std::map<int, double> mismatch;
  for (int level : {2, 3}) {
    const auto frame = renderFrame(
        rig, tessellation(TessellationMode::CrackFree, TessellationMetric::Pixels, 0.0f, level), kWidth, kHeight);
    EXPECT_EQ(frame.tessellation.capped, level == 3) << "level " << level;
    mismatch[level] = specula::testing::mismatchAgainst(*truth, frame).share;
  }
  std::printf("kitchen, full tessellation: mismatch %.4f at level 2, %.4f at level 3 (capped)\n", mismatch[2],
              mismatch[3]);
  EXPECT_LE(mismatch[3], mismatch[2] + 0.002);
}
