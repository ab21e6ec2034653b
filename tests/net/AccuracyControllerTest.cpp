// The accuracy target's controller, fed windows of live estimates by hand (no GL, no tracer).
#include <gtest/gtest.h>

#include "session/AccuracyController.h"

namespace specula::session {
namespace {

constexpr double kTarget = 0.005;  // 0.5 %

// A window of `frames` frames of 256 sampled pixels each, `share` of them wrong.
reference::ShareEstimate window(double share, std::size_t frames = AccuracyController::kSettleFrames) {
  const std::size_t sampled = 256 * frames;
  return reference::wilsonInterval(static_cast<std::size_t>(share * static_cast<double>(sampled) + 0.5), sampled);
}

std::size_t rungNamed(const AccuracyController& controller, const std::vector<AccuracyRung>& ladder,
                      const std::string& name) {
  for (std::size_t i = 0; i < ladder.size(); ++i)
    if (ladder[i].name == name) return i;
  ADD_FAILURE() << "no rung " << name << " (current " << controller.current().name << ")";
  return 0;
}

TEST(AccuracyLadder, RunsFromTheEnvironmentMapToEveryMirrorRayCastWithoutDuplicates) {
  const std::vector<AccuracyRung> ladder = accuracyLadder({});
  ASSERT_EQ(ladder.size(), 4u);
  EXPECT_EQ(ladder.front().settings.method, passes::ReflectionMethod::EnvironmentMap);
  EXPECT_EQ(ladder[1].settings.tessellation.mode, passes::TessellationMode::None);
  EXPECT_TRUE(ladder.back().exact);
  EXPECT_EQ(ladder.back().settings.rayCast, passes::RayCastRule::Always);
  passes::ReflectionSettings alreadyCast;
  alreadyCast.rayCast = passes::RayCastRule::Always;
  EXPECT_EQ(accuracyLadder(alreadyCast).size(), 3u) << "the session's own settings are the exact rung";
}

TEST(AccuracyController, StartsExactStepsDownWhenComfortablyUnderAndUpWhenTheEstimateCrossesTheTarget) {
  const std::vector<AccuracyRung> ladder = accuracyLadder({});
  AccuracyController controller(ladder, kTarget);
  EXPECT_TRUE(controller.current().exact);
  EXPECT_FALSE(controller.windowMeasured(window(0.0, 3), 3, 3)) << "a window of 3 frames has not settled";
  ASSERT_TRUE(controller.windowMeasured(window(0.0), 8, 8));
  EXPECT_EQ(controller.rung(), 0u) << "the cheapest setting is tried first";
  EXPECT_NE(controller.reason().find("trying environment map"), std::string::npos) << controller.reason();
  // The environment map is 13 % off up close: one frame's interval is wholly over the target.
  ASSERT_TRUE(controller.windowMeasured(window(0.13, 1), 1, 9));
  EXPECT_EQ(controller.rung(), 1u);
  EXPECT_NE(controller.reason().find("exceeds 0.50 %"), std::string::npos) << controller.reason();
  // The untessellated search at 0.3 %: under the target, but not under half of it: it stays.
  for (std::uint64_t frame = 10; frame < 40; ++frame) EXPECT_FALSE(controller.windowMeasured(window(0.003), 8, frame));
  EXPECT_EQ(controller.rung(), 1u);
  EXPECT_TRUE(controller.met());
}

TEST(AccuracyController, ASettingThatFailedIsNotRetriedUntilItsCooldownWhichDoubles) {
  const std::vector<AccuracyRung> ladder = accuracyLadder({});
  AccuracyController controller(ladder, kTarget);
  std::vector<std::uint64_t> triedAt;
  // Every frame: the environment map fails, anything else is exact-clean.
  for (std::uint64_t frame = 1; frame <= 600; ++frame) {
    const bool onEnvironmentMap = controller.rung() == 0;
    if (onEnvironmentMap) triedAt.push_back(frame);
    controller.windowMeasured(onEnvironmentMap ? window(0.2, 1) : window(0.0), onEnvironmentMap ? 1 : 8, frame);
  }
  // Tried at frame 1 (from exact), then after 60, 120, 240 frames: not back and forth every frame.
  ASSERT_GE(triedAt.size(), 3u);
  EXPECT_LE(triedAt.size(), 5u);
  for (std::size_t i = 2; i < triedAt.size(); ++i)
    EXPECT_GE(triedAt[i] - triedAt[i - 1], 2 * (triedAt[i - 1] - triedAt[i - 2]) - 2) << "the cool-down doubles";
}

TEST(AccuracyController, ATargetNoSettingMeetsIsReportedAndTheMostAccurateKept) {
  const std::vector<AccuracyRung> ladder = accuracyLadder({});
  AccuracyController controller(ladder, 0.0001);
  EXPECT_FALSE(controller.windowMeasured(window(0.01, 2), 2, 2));
  EXPECT_TRUE(controller.current().exact);
  EXPECT_FALSE(controller.met());
  EXPECT_NE(controller.reason().find("no setting meets 0.01 %"), std::string::npos) << controller.reason();
}

TEST(AccuracyController, ACheaperSettingMeasuredDearerIsNotChosen) {
  const std::vector<AccuracyRung> ladder = accuracyLadder({});
  AccuracyController controller(ladder, kTarget);
  const std::size_t exact = controller.rung();
  controller.frameRendered(exact, 10.0);
  controller.frameRendered(0, 30.0);  // the environment map measured three times dearer
  ASSERT_TRUE(controller.windowMeasured(window(0.0), 8, 8));
  EXPECT_EQ(controller.rung(), rungNamed(controller, ladder, "virtual objects without tessellation"));
  EXPECT_FALSE(controller.windowMeasured(reference::ShareEstimate{}, 0, 9)) << "no mirror sampled: nothing learnt";
  // Searching turns out dearer than casting every mirror, which is exact: back to casting.
  controller.frameRendered(controller.rung(), 20.0);
  ASSERT_TRUE(controller.windowMeasured(window(0.001, 1), 1, 10));
  EXPECT_EQ(controller.rung(), exact);
  EXPECT_NE(controller.reason().find("exact and was measured cheaper"), std::string::npos) << controller.reason();
}

}  // namespace
}  // namespace specula::session
