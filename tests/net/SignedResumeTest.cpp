// Stateless resume tokens (issue #21): the state survives the trip through a token, any instance
// sharing the secret resumes it, and an altered, expired or foreign token is refused by name, never
// crashing the server (this file also runs under AddressSanitizer and UBSan).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "ServerRig.h"
#include "base/Base64Url.h"
#include "session/SettingsProtocol.h"
#include "session/SignedResume.h"

namespace specula::testing {
namespace {

const std::string kSecret(40, 'k');

struct WallClockOffset {
  std::chrono::seconds value{0};
};

TEST(Base64Url, RoundTripsAnyBytesAndRefusesOtherAlphabets) {
  std::mt19937 random(3);
  for (std::size_t length = 0; length < 80; ++length) {
    std::string bytes(length, '\0');
    for (char& c : bytes) c = static_cast<char>(random());
    const std::string text = base64UrlEncode(bytes);
    EXPECT_EQ(text.find_first_of("+/="), std::string::npos);
    EXPECT_EQ(base64UrlDecode(text), bytes) << length;
  }
  EXPECT_EQ(base64UrlEncode("\xfb\xff"), "-_8");
  for (const char* bad : {"a", "ab=c", "a+bc", "a/bc", "ab c", "AB"})  // "AB": leftover bits set
    EXPECT_FALSE(base64UrlDecode(bad).has_value()) << bad;
}

session::SessionState aViewedState(session::Clock::time_point now) {
  session::SessionState state;
  state.width = 320;
  state.height = 200;
  state.camera = math::Camera{{1.5f, 2.0f, 7.0f}, {0.0f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}, 38.0f};
  state.clock.setSpeed(2.0f, now);
  state.clock.seek(1234.5, now);
  state.overrides[1] = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, -2.0f));
  state.settings.stillSamples = 8;
  state.settings.jpegQuality = 70;
  state.settings.reflection.search = passes::SearchStrategy::Hierarchy;
  state.settings.reflection.tessellation.maxLevel = 2;
  return state;
}

TEST(SignedResume, CarriesTheWholeStateThroughAToken) {
  const auto scene = scene::makeBuiltinScene("checker-sphere");
  auto tokens = session::SignedResume::create(kSecret, std::chrono::seconds(60), *scene);
  ASSERT_TRUE(tokens) << tokens.error();
  const auto now = session::Clock::now();
  const auto wall = session::WallClock::now();
  const session::SessionState state = aViewedState(now);
  const std::string token = tokens->issue(state, now, wall);
  EXPECT_TRUE(token.starts_with("s1."));
  EXPECT_LT(token.size(), 1024u);
  auto opened = tokens->open(token, {}, now + std::chrono::seconds(5), wall + std::chrono::seconds(5));
  ASSERT_TRUE(opened) << opened.error();
  EXPECT_EQ(opened->width, 320);
  ASSERT_TRUE(opened->camera);
  EXPECT_EQ(opened->camera->eye, state.camera->eye);
  EXPECT_FLOAT_EQ(opened->camera->fovYDegrees, 38.0f);
  EXPECT_DOUBLE_EQ(opened->clock.sceneMs(now + std::chrono::seconds(9)), 1234.5) << "paused at the token's time";
  EXPECT_FALSE(opened->playOnResume);
  EXPECT_FLOAT_EQ(opened->clock.speed(), 2.0f);
  ASSERT_EQ(opened->overrides.size(), 1u);
  EXPECT_EQ(opened->overrides.at(1), state.overrides.at(1));
  EXPECT_EQ(session::settingsToProto(opened->settings).SerializeAsString(),
            session::settingsToProto(state.settings).SerializeAsString());
}

TEST(SignedResume, RefusesAlteredForeignExpiredAndMalformedTokensByName) {
  const auto scene = scene::makeBuiltinScene("checker-sphere");
  const auto now = session::Clock::now();
  const auto wall = session::WallClock::now();
  auto tokens = session::SignedResume::create(kSecret, std::chrono::seconds(60), *scene);
  ASSERT_TRUE(tokens);
  const std::string token = tokens->issue(aViewedState(now), now, wall);
  const auto refusal = [&](std::string_view candidate, WallClockOffset offset = {}) {
    auto opened = tokens->open(candidate, {}, now, wall + offset.value);
    return opened ? std::string("opened") : opened.error();
  };
  std::string altered = token;
  altered[10] = altered[10] == 'A' ? 'B' : 'A';
  EXPECT_NE(refusal(altered).find("its signature does not match"), std::string::npos) << refusal(altered);
  auto otherSecret = session::SignedResume::create(std::string(40, 'z'), std::chrono::seconds(60), *scene);
  EXPECT_NE(refusal(otherSecret->issue(aViewedState(now), now, wall)).find("another secret"), std::string::npos);
  auto otherScene =
      session::SignedResume::create(kSecret, std::chrono::seconds(60), *scene::makeBuiltinScene("kitchen"));
  EXPECT_NE(refusal(otherScene->issue(aViewedState(now), now, wall)).find("issued for another scene"),
            std::string::npos);
  EXPECT_NE(refusal(token, {std::chrono::seconds(61)}).find("it expired"), std::string::npos);
  EXPECT_EQ(refusal(token, {std::chrono::seconds(59)}), "opened");
  for (const std::string& garbage :
       {std::string(), std::string("s1."), std::string("s1.."), std::string("s1.abc.def"), std::string("x") + token,
        std::string(session::SignedResume::kMaxTokenBytes + 1, 'a'), token.substr(0, token.size() - 1)})
    EXPECT_NE(refusal(garbage), "opened") << garbage.substr(0, 40);
  EXPECT_TRUE(session::SignedResume::secretProblem("short").has_value());
  EXPECT_FALSE(session::SignedResume::create("short", std::chrono::seconds(60), *scene));
}

TEST(SignedResume, RandomMutationsOfATokenNeverOpenOrCrash) {
  const auto scene = scene::makeBuiltinScene("checker-sphere");
  auto tokens = session::SignedResume::create(kSecret, std::chrono::seconds(60), *scene);
  ASSERT_TRUE(tokens);
  const auto now = session::Clock::now();
  const std::string token = tokens->issue(aViewedState(now), now, session::WallClock::now());
  std::mt19937 random(11);
  for (int i = 0; i < 2000; ++i) {
    std::string mutated = token;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) mutated[random() % mutated.size()] = static_cast<char>(random());
    if (mutated == token) continue;
    EXPECT_FALSE(tokens->open(mutated, {}, now, session::WallClock::now())) << i;
  }
}

// The service end to end: two instances sharing a secret, one with another.
RigOptions signedRig(const std::string& secret) {
  RigOptions options = defaultRigOptions();
  options.hub.resumeSecret = secret;
  return options;
}

TEST(SignedResume, AnotherInstanceWithTheSecretResumesTheSessionFromItsLatestFrame) {
  ServerRig first(signedRig(kSecret)), second(signedRig(kSecret)), stranger(signedRig(std::string(40, 'q')));
  auto client = first.connect(protocol::Encoding::Json);
  ASSERT_TRUE(client);
  greet(*client);
  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::SEEK, 2500.0)).ok());
  ASSERT_TRUE(client->send(cameraMessage({2, 1, 5}, 7)).ok());
  v1::ClientMessage settings;
  settings.mutable_settings()->set_search(v1::SEARCH_HIERARCHY);
  settings.mutable_settings()->set_still_samples(2);
  ASSERT_TRUE(client->send(settings).ok());
  // The first frame after the settings change echoes them; messages apply in order, so the camera is in too.
  auto frame = receiveUntil(*client, [](const v1::ServerMessage& m) {
    return m.has_frame() && m.frame().has_settings() && m.frame().settings().search() == v1::SEARCH_HIERARCHY;
  });
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->frame().input_sequence(), 7u);
  const std::string token = frame->frame().resume_token();
  ASSERT_FALSE(token.empty()) << "with a secret every frame carries the state's token";
  first.stop();  // the instance is gone

  auto moved = second.connect(protocol::Encoding::Proto);
  ASSERT_TRUE(moved);
  const v1::Welcome welcome = greet(*moved, 64, 48, token);
  EXPECT_TRUE(welcome.resumed());
  EXPECT_FLOAT_EQ(welcome.camera().eye().x(), 2.0f);
  EXPECT_FLOAT_EQ(welcome.camera().eye().z(), 5.0f);
  EXPECT_FALSE(welcome.playing());
  EXPECT_DOUBLE_EQ(welcome.scene_time_ms(), 2500.0);
  EXPECT_EQ(welcome.settings().search(), v1::SEARCH_HIERARCHY);
  EXPECT_EQ(welcome.settings().still_samples(), 2u);
  EXPECT_FALSE(receiveUntil(
      *moved, [](const v1::ServerMessage& m) { return m.has_error(); }, 300ms))
      << "no error for a good token";
  // Stateless: the same token resumes again (until it expires), on any instance with the secret.
  auto again = second.connect(protocol::Encoding::Proto);
  EXPECT_TRUE(greet(*again, 64, 48, token).resumed());

  auto refused = stranger.connect(protocol::Encoding::Proto);
  ASSERT_TRUE(refused);
  EXPECT_FALSE(greet(*refused, 64, 48, token).resumed()) << "another secret: a fresh session";
  auto error = receiveUntil(*refused, [](const v1::ServerMessage& m) { return m.has_error(); });
  ASSERT_TRUE(error);
  EXPECT_EQ(error->error().code(), v1::Error::RESUME_REFUSED);
  EXPECT_NE(error->error().message().find("another secret"), std::string::npos) << error->error().message();
  EXPECT_TRUE(receiveUntil(*refused, isFrame)) << "the fresh session streams";
  EXPECT_NE(httpRequest(stranger.port(), "/metrics").body.find("specula_resumes_refused_total 1"), std::string::npos);
}

TEST(SignedResume, WithoutASecretFramesCarryNoTokenAndAnUnknownTokenIsSaidSo) {
  ServerRig rig;
  auto client = rig.connect(protocol::Encoding::Proto);
  ASSERT_TRUE(client);
  greet(*client, 64, 48, "0123456789abcdef0123456789abcdef");
  auto error = receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_error(); });
  ASSERT_TRUE(error);
  EXPECT_EQ(error->error().code(), v1::Error::RESUME_REFUSED);
  auto frame = receiveUntil(*client, isFrame);
  ASSERT_TRUE(frame);
  EXPECT_TRUE(frame->frame().resume_token().empty());
}

TEST(Readiness, ReadyzSaysWhetherToSendNewSessionsHere) {
  RigOptions options = defaultRigOptions();
  options.hub.maxSessions = 1;
  options.server.token = "t0ken";
  ServerRig rig(options);
  const HttpReply ready = httpRequest(rig.port(), "/readyz");
  EXPECT_EQ(ready.status, 200) << "needs no token";
  EXPECT_EQ(ready.body, "ready\n");
  auto client = rig.connect(protocol::Encoding::Proto, "t0ken");
  ASSERT_TRUE(client);
  greet(*client);
  const HttpReply full = httpRequest(rig.port(), "/readyz");
  EXPECT_EQ(full.status, 503);
  EXPECT_EQ(full.body, "full\n");
  rig.hub().refuseNewSessions();
  EXPECT_EQ(httpRequest(rig.port(), "/readyz").body, "draining\n");
  const std::string metrics = rig.hub().prometheusText();
  for (const char* gauge : {"specula_sessions_capacity 1", "specula_render_queue_depth ", "specula_draining 1"})
    EXPECT_NE(metrics.find(gauge), std::string::npos) << gauge;
  EXPECT_EQ(httpRequest(rig.port(), "/metrics").status, 401) << "metrics keep the token unless served publicly";
}

}  // namespace
}  // namespace specula::testing
