// The live accuracy estimate (reference::sampleMirrorMismatch) against the full comparison it
// estimates (reference::maskedMismatch over the exact image), on frames corrupted in known ways.
#include <gtest/gtest.h>

#include <random>

#include "reference/MismatchSample.h"
#include "reference/PixelTracer.h"
#include "reference/RayTracer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"

using namespace specula;

namespace {

constexpr int kWidth = 320, kHeight = 240;

struct Fixture {
  std::shared_ptr<const scene::Scene> scene;
  std::unique_ptr<reference::RayTracer> tracer;
  scene::ScenePose pose;
  reference::ReferenceImage exact;
  std::unique_ptr<reference::PixelTracer> pixels;
};

Fixture checkerSphere() {
  Fixture f;
  f.scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("checker-sphere"));
  auto tracer = reference::RayTracer::create(f.scene);
  f.tracer = std::move(*tracer);
  f.pose = scene::ScenePose::at(*f.scene, 0.0);
  f.exact = *f.tracer->render(f.pose, {kWidth, kHeight, 1, 1, 1});
  auto pixels = f.tracer->pixelTracer(*f.tracer->posedScene(f.pose), f.pose.camera, {kWidth, kHeight, 1, 1, 1});
  f.pixels = std::move(*pixels);
  return f;
}

double fullMismatch(const Fixture& f, const std::vector<std::uint8_t>& frame) {
  return reference::maskedMismatch({frame, kWidth, kHeight}, {f.exact.rgba, kWidth, kHeight}, f.exact.mirrorMask)
      ->share();
}

reference::MismatchSample estimate(const Fixture& f, const std::vector<std::uint8_t>& frame, std::uint64_t seed,
                                   int pixels = reference::kDefaultAccuracySamples) {
  reference::MismatchSampleOptions options;
  options.seed = seed;
  options.pixels = pixels;
  return *reference::sampleMirrorMismatch(*f.pixels, {frame, kWidth, kHeight}, options);
}

// The frame with rows [top, bottom) blacked out: the test hook standing for a wrong band of mirror.
std::vector<std::uint8_t> blackBand(std::vector<std::uint8_t> frame, int top, int bottom) {
  for (int row = top; row < bottom; ++row)
    for (int column = 0; column < kWidth; ++column)
      for (int c = 0; c < 3; ++c) frame[4 * (static_cast<std::size_t>(row) * kWidth + column) + c] = 0;
  return frame;
}

struct Calibration {
  double coverage = 0.0;  // the share of the estimates whose interval contains the truth
  double meanEstimate = 0.0;
};

// `seeds` estimates of one frame, each from its own sample.
Calibration calibrate(const Fixture& f, const std::vector<std::uint8_t>& frame, double truth, int seeds) {
  Calibration c;
  for (int seed = 0; seed < seeds; ++seed) {
    const reference::ShareEstimate e = estimate(f, frame, static_cast<std::uint64_t>(seed)).mismatch;
    c.coverage += e.low <= truth && truth <= e.high ? 1.0 / seeds : 0.0;
    c.meanEstimate += e.share() / seeds;
  }
  return c;
}

}  // namespace

TEST(WilsonInterval, MatchesTheScoreIntervalsFormula) {
  // 10 of 100: Wilson's 95 % interval is [0.0552, 0.1744] (Newcombe 1998, method 3).
  const reference::ShareEstimate tenth = reference::wilsonInterval(10, 100);
  EXPECT_NEAR(tenth.low, 0.0552, 5e-5);
  EXPECT_NEAR(tenth.high, 0.1744, 5e-5);
  // None of 256: [0, z² / (n + z²)].
  const reference::ShareEstimate none = reference::wilsonInterval(0, 256);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 3.8415 / (256 + 3.8415), 1e-5);
  const reference::ShareEstimate all = reference::wilsonInterval(40, 40);
  EXPECT_EQ(all.high, 1.0);
  EXPECT_NEAR(all.low, 40.0 / (40 + 3.8415), 1e-4);
  const reference::ShareEstimate nothing = reference::wilsonInterval(0, 0);
  EXPECT_EQ(nothing.low, 0.0);
  EXPECT_EQ(nothing.high, 1.0);
}

TEST(MismatchSample, TheExactImageIsEstimatedExactAndEverySampleIsOnTheMirror) {
  const Fixture f = checkerSphere();
  const reference::MismatchSample sample = estimate(f, f.exact.rgba, 7);
  EXPECT_EQ(sample.mismatch.sampled, 256u);
  EXPECT_EQ(sample.mismatch.hits, 0u);
  EXPECT_EQ(sample.mismatch.low, 0.0);
  EXPECT_LT(sample.mismatch.high, 0.015);
  // Every sampled pixel is a mirror pixel: blacking out everything but the mirror changes nothing.
  std::vector<std::uint8_t> onlyMirror = f.exact.rgba;
  for (std::size_t i = 0; i < f.exact.mirrorMask.size(); ++i)
    if (!f.exact.mirrorMask[i]) onlyMirror[4 * i] = onlyMirror[4 * i + 1] = onlyMirror[4 * i + 2] = 0;
  EXPECT_EQ(estimate(f, onlyMirror, 7).mismatch.hits, 0u);
  // The probes stop once enough mirror pixels are found.
  EXPECT_LT(sample.probedPixels, static_cast<std::size_t>(kWidth * kHeight) / 4);
}

TEST(MismatchSample, ABlackedOutBandRaisesTheEstimateToWhatTheFullComparisonMeasures) {
  const Fixture f = checkerSphere();
  // Bands through the sphere's middle and its lower rim: large and small shares of its pixels.
  for (const auto& [top, bottom] : {std::pair{100, 140}, std::pair{150, 156}}) {
    const std::vector<std::uint8_t> corrupted = blackBand(f.exact.rgba, top, bottom);
    const double truth = fullMismatch(f, corrupted);
    ASSERT_GT(truth, 0.0) << "the band must cross the mirror";
    const reference::MismatchSample sample = estimate(f, corrupted, 3);
    EXPECT_GT(sample.mismatch.hits, 0u);
    EXPECT_LE(sample.mismatch.low, truth);
    EXPECT_GE(sample.mismatch.high, truth);
    EXPECT_GE(calibrate(f, corrupted, truth, 100).coverage, 0.9)
        << "band " << top << ".." << bottom << ", truth " << truth;
  }
}

TEST(MismatchSample, CoversScatteredErrorsAtTheNominalRateWithoutBias) {
  const Fixture f = checkerSphere();
  // Every mirror pixel wrong with probability q: no spatial structure for the walk to exploit.
  for (const double q : {0.01, 0.05, 0.3}) {
    std::vector<std::uint8_t> corrupted = f.exact.rgba;
    std::mt19937 random(11);
    std::bernoulli_distribution wrong(q);
    for (std::size_t i = 0; i < f.exact.mirrorMask.size(); ++i)
      if (f.exact.mirrorMask[i] && wrong(random)) corrupted[4 * i] = static_cast<std::uint8_t>(corrupted[4 * i] ^ 0x80);
    const double truth = fullMismatch(f, corrupted);
    const Calibration c = calibrate(f, corrupted, truth, 200);
    EXPECT_GE(c.coverage, 0.9) << "q " << q << ", truth " << truth;        // measured 0.955 to 0.98
    EXPECT_NEAR(c.meanEstimate, truth, 0.05 * truth + 5e-4) << "q " << q;  // unbiased: measured within 2 %
  }
}

TEST(MismatchSample, RefusesMismatchedSizesAndSampleCountsOutOfRange) {
  const Fixture f = checkerSphere();
  const std::vector<std::uint8_t> small(4 * 16 * 16, 0);
  auto wrongSize = reference::sampleMirrorMismatch(*f.pixels, {small, 16, 16}, {});
  ASSERT_FALSE(wrongSize);
  EXPECT_NE(wrongSize.error().find("16x16"), std::string::npos) << wrongSize.error();
  for (const int pixels : {0, -5, reference::kMaxAccuracySamples + 1}) {
    reference::MismatchSampleOptions options;
    options.pixels = pixels;
    auto refused = reference::sampleMirrorMismatch(*f.pixels, {f.exact.rgba, kWidth, kHeight}, options);
    ASSERT_FALSE(refused) << pixels;
    EXPECT_NE(refused.error().find("sample pixels"), std::string::npos) << refused.error();
  }
}

TEST(MismatchSample, AViewWithoutMirrorSamplesNothingAndClaimsNothing) {
  Fixture f = checkerSphere();
  scene::ScenePose away = f.pose;
  away.camera.target = away.camera.eye + (away.camera.eye - away.camera.target);  // look away from the sphere
  auto pixels = f.tracer->pixelTracer(*f.tracer->posedScene(away), away.camera, {kWidth, kHeight, 1, 1, 1});
  ASSERT_TRUE(pixels) << pixels.error();
  reference::MismatchSampleOptions options;
  auto sample = reference::sampleMirrorMismatch(**pixels, {f.exact.rgba, kWidth, kHeight}, options);
  ASSERT_TRUE(sample) << sample.error();
  EXPECT_EQ(sample->mismatch.sampled, 0u);
  EXPECT_EQ(sample->mismatch.low, 0.0);
  EXPECT_EQ(sample->mismatch.high, 1.0);
  EXPECT_EQ(sample->probedPixels, 256u * 64u);
}
