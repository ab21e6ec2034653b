// The live accuracy estimate in the stream: frames carry the estimate of an earlier frame, made by the
// reference ray tracer on the fake renderer's flat grey frames (which are wrong on nearly every mirror
// pixel of checker-sphere), a setting turns it off, and bad values are refused by name.
#include <gtest/gtest.h>

#include "ServerRig.h"

namespace specula::testing {
namespace {

using namespace std::chrono_literals;

// Asks for frames with camera updates until one carries an estimate (or `tries` frames came without). The
// sampler runs at the lowest CPU priority: beside other tests on a busy machine its estimates come late.
std::optional<v1::Frame> frameWithEstimate(client::SpeculaClient& client, std::uint64_t& sequence, int tries = 400) {
  for (int i = 0; i < tries; ++i) {
    EXPECT_TRUE(client.send(cameraMessage({0.2f * static_cast<float>(i % 3), 1.0f, 6.0f}, ++sequence)).ok());
    auto frame = receiveUntil(client, isFrame);
    if (!frame) return std::nullopt;
    if (frame->frame().has_accuracy()) return frame->frame();
    std::this_thread::sleep_for(20ms);
  }
  return std::nullopt;
}

TEST(LiveAccuracy, FramesCarryTheEstimateOfAnEarlierFramePooledOverAWindow) {
  ServerRig rig;
  auto client = rig.connect();
  ASSERT_TRUE(client);
  greet(*client, 160, 120);
  std::uint64_t sequence = 0;
  auto first = frameWithEstimate(*client, sequence);
  ASSERT_TRUE(first) << "no frame carried an accuracy estimate";
  const v1::AccuracyEstimate& estimate = first->accuracy();
  EXPECT_LT(estimate.frame(), first->number()) << "estimated beside rendering, it arrives with a later frame";
  EXPECT_EQ(estimate.sampled(), 256u);
  EXPECT_GE(estimate.probed(), estimate.sampled());
  EXPECT_GT(estimate.mismatch(), 0.9) << "a flat grey frame is wrong on almost every mirror pixel";
  EXPECT_LE(estimate.low(), estimate.mismatch());
  EXPECT_GE(estimate.high(), estimate.mismatch());
  EXPECT_GT(estimate.trace_ms(), 0.0);
  // More frames: the window pools them, so its interval narrows.
  std::optional<v1::Frame> later;
  for (int i = 0; i < 40 && (!later || later->accuracy().window_frames() < 3); ++i)
    later = frameWithEstimate(*client, sequence);
  ASSERT_TRUE(later);
  const v1::AccuracyEstimate& pooled = later->accuracy();
  EXPECT_GE(pooled.window_frames(), 3u);
  EXPECT_EQ(pooled.window_sampled(), 256u * pooled.window_frames());
  EXPECT_LT(pooled.window_high() - pooled.window_low(), estimate.high() - estimate.low());
  const HttpReply metrics = httpRequest(rig.port(), "/metrics");
  EXPECT_NE(metrics.body.find("specula_accuracy_mismatch_percent_bucket"), std::string::npos);
  EXPECT_NE(metrics.body.find("specula_accuracy_milliseconds_count"), std::string::npos);
}

TEST(LiveAccuracy, AStillViewGetsTheEstimateOfTheFrameOnScreenWithoutNewInput) {
  ServerRig rig;
  auto client = rig.connect();
  ASSERT_TRUE(client);
  greet(*client, 160, 120);
  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  std::uint64_t lastRendered = 0;
  std::optional<v1::AccuracyEstimate> own;
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (!own && std::chrono::steady_clock::now() < deadline) {
    auto message = client->receive(200ms);
    if (!message) continue;
    if (message->has_frame() && !message->frame().reencoded()) lastRendered = message->frame().number();
    if (message->has_accuracy() && message->accuracy().frame() == lastRendered) own = message->accuracy();
  }
  ASSERT_TRUE(own) << "the last frame rendered, " << lastRendered << ", got no estimate of its own";
  EXPECT_EQ(own->sampled(), 256u);
}

TEST(LiveAccuracy, ZeroSamplesTurnItOffAndValuesOutOfRangeAreRefusedByName) {
  ServerRig rig;
  auto client = rig.connect(protocol::Encoding::Json);
  ASSERT_TRUE(client);
  const v1::Welcome welcome = greet(*client, 96, 72);
  EXPECT_EQ(welcome.settings().accuracy_samples(), 256);
  for (const char* bad : {R"({"settings":{"accuracySamples":65537}})", R"({"settings":{"accuracySamples":-2}})"}) {
    ASSERT_TRUE(client->sendRaw(bad, true).ok());
    auto error = receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_error(); });
    ASSERT_TRUE(error) << bad;
    EXPECT_EQ(error->error().code(), v1::Error::BAD_VALUE) << bad;
    EXPECT_NE(error->error().message().find("accuracy_samples"), std::string::npos) << error->error().message();
  }
  std::uint64_t sequence = 0;
  ASSERT_TRUE(frameWithEstimate(*client, sequence)) << "on by default";
  ASSERT_TRUE(client->sendRaw(R"({"settings":{"accuracySamples":-1}})", true).ok());
  auto changed =
      receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().has_settings(); });
  ASSERT_TRUE(changed);
  EXPECT_EQ(changed->frame().settings().accuracy_samples(), -1) << "0, sent as -1";
  EXPECT_FALSE(frameWithEstimate(*client, sequence, 10)) << "off: no frame carries an estimate";
}

TEST(LiveAccuracy, ATargetNoSettingMeetsEndsOnTheMostAccurateAndSaysSo) {
  ServerRig rig;
  auto client = rig.connect(protocol::Encoding::Json);
  ASSERT_TRUE(client);
  greet(*client, 160, 120);
  for (const char* bad : {R"({"settings":{"accuracyTarget":150}})", R"({"settings":{"accuracyTarget":-3}})",
                          R"({"settings":{"accuracyTarget":1,"accuracySamples":-1}})"}) {
    ASSERT_TRUE(client->sendRaw(bad, true).ok());
    auto error = receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_error(); });
    ASSERT_TRUE(error) << bad;
    EXPECT_EQ(error->error().code(), v1::Error::BAD_VALUE) << bad;
    EXPECT_NE(error->error().message().find("accuracy_"), std::string::npos) << error->error().message();
  }
  // The fake renderer's grey frames are wrong whatever is asked: even the exact setting misses 0.5 %.
  ASSERT_TRUE(client->sendRaw(R"({"settings":{"accuracyTarget":0.5}})", true).ok());
  std::uint64_t sequence = 0;
  std::optional<v1::Frame> reported;
  for (int i = 0; i < 200 && !(reported && reported->has_accuracy_control() && !reported->accuracy_control().met());
       ++i)
    reported = frameWithEstimate(*client, sequence);
  ASSERT_TRUE(reported && reported->has_accuracy_control());
  const v1::AccuracyControl& control = reported->accuracy_control();
  EXPECT_FLOAT_EQ(control.target(), 0.5f);
  EXPECT_EQ(control.setting(), "every mirror ray-cast");
  EXPECT_FALSE(control.met());
  EXPECT_NE(control.reason().find("no setting meets 0.50 %"), std::string::npos) << control.reason();
}

TEST(LiveAccuracy, SessionsClosingWhileTheirFramesAreTracedLeaveNothingBehind) {
  ServerRig rig;
  for (int i = 0; i < 20; ++i) {
    auto client = rig.connect();
    ASSERT_TRUE(client);
    greet(*client, 320, 240);
    ASSERT_TRUE(receiveUntil(*client, isFrame));  // its first frame is queued for the sampler
  }
  const auto deadline = std::chrono::steady_clock::now() + 3s;
  while (rig.hub().sessionCount() > 0 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
  EXPECT_EQ(rig.hub().sessionCount(), 0u);
  auto client = rig.connect();
  ASSERT_TRUE(client);
  greet(*client, 160, 120);
  std::uint64_t sequence = 0;
  EXPECT_TRUE(frameWithEstimate(*client, sequence)) << "the sampler still serves new sessions";
}

}  // namespace
}  // namespace specula::testing
