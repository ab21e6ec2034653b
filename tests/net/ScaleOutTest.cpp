// Many instances behind HAProxy on loopback (issue #21): sessions spread by the balancer, survive
// losing their instance (killed, or drained) with camera, animation time and settings, and the
// other sessions never notice. Real `specula serve` processes (software GL is fine), real HAProxy
// with docker/haproxy/specula.cfg, clients that reconnect and resume as the tools do.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "CameraConversions.h"
#include "ResumingClient.h"
#include "app/LoopbackCluster.h"
#include "base/Base64Url.h"

namespace specula::testing {
namespace {

using namespace std::chrono_literals;

constexpr int kInstances = 3;
constexpr int kSessions = 12;

struct Viewer {
  std::unique_ptr<client::ResumingClient> client;
  std::string instance;  // Welcome.instance: "host:pid" of the process serving it now
  glm::vec3 eye{0.0f};
  double sceneMs = 0.0;
  // What the client said about its connection; shared with its notice callback, which outlives moves of the viewer.
  std::shared_ptr<std::vector<std::string>> notices = std::make_shared<std::vector<std::string>>();
  std::vector<std::string> errors;  // error messages the server sent
};

v1::Hello hello() {
  v1::Hello message;
  message.set_protocol_version(1);
  message.set_width(64);
  message.set_height(48);
  return message;
}

// Reads until a message satisfies `accept`, noting welcomes and errors; false on timeout or loss.
bool readUntil(Viewer& viewer, const std::function<bool(const v1::ServerMessage&)>& accept,
               std::chrono::milliseconds timeout = 30s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    auto message = viewer.client->receive(
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
    if (!message) {
      if (viewer.client->closeInfo()) return false;
      continue;
    }
    if (message->has_welcome()) viewer.instance = message->welcome().instance();
    if (message->has_error())
      viewer.errors.push_back(v1::Error::Code_Name(message->error().code()) + ": " + message->error().message());
    if (accept(*message)) return true;
  }
  return false;
}

// The welcome of the connection the viewer's client made after losing its old one.
std::optional<v1::Welcome> welcomeAfterReconnect(Viewer& viewer) {
  std::optional<v1::Welcome> welcome;
  readUntil(viewer, [&](const v1::ServerMessage& m) {
    if (m.has_welcome()) welcome = m.welcome();
    return m.has_welcome();
  });
  return welcome;
}

std::string pidOf(const std::string& instance) { return instance.substr(instance.rfind(':') + 1); }

class ScaleOut : public ::testing::Test {
 protected:
  void SetUp() override {
    app::LoopbackClusterOptions options;
    options.specula = SPECULA_BINARY;
    options.haproxyConfig = SPECULA_HAPROXY_CONFIG;
    options.instances = kInstances;
    options.resumeSecret = std::string(48, 'r');
    options.drainSeconds = 3;
    options.serveArguments = {"--scene", "quad", "--max-sessions", "16", "--still-delay", "50"};
    auto cluster = app::LoopbackCluster::start(options);
    ASSERT_TRUE(cluster) << cluster.error();
    cluster_ = std::move(*cluster);
  }

  // A viewer through the front, greeted, paused at its own time and camera, with its own settings.
  Viewer connectViewer(int i) {
    Viewer viewer;
    auto client = client::ResumingClient::connect(
        {"127.0.0.1", cluster_->frontPort(), ""}, protocol::Encoding::Proto, hello(), {12, 100ms, 1000ms, 3000ms},
        [notices = viewer.notices](const std::string& notice) { notices->push_back(notice); });
    EXPECT_TRUE(client) << client.error();
    if (!client) return viewer;
    viewer.client = std::move(*client);
    EXPECT_TRUE(readUntil(viewer, [](const v1::ServerMessage& m) { return m.has_welcome(); }));
    viewer.eye = glm::vec3(1.0f + 0.25f * static_cast<float>(i), 1.5f, 6.0f);
    viewer.sceneMs = 1000.0 + 125.0 * i;
    v1::ClientMessage pause, seek, camera, settings;
    pause.mutable_animation()->set_action(v1::AnimationControl::PAUSE);
    seek.mutable_animation()->set_action(v1::AnimationControl::SEEK);
    seek.mutable_animation()->set_time_ms(viewer.sceneMs);
    *camera.mutable_camera() = protocol::cameraUpdate(viewer.eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 40.0f);
    camera.mutable_camera()->set_sequence(1);
    settings.mutable_settings()->set_still_samples(i % 2 == 0 ? 2 : 8);
    settings.mutable_settings()->set_jpeg_quality(static_cast<std::uint32_t>(50 + i));
    for (const v1::ClientMessage* message : {&pause, &seek, &camera, &settings})
      EXPECT_TRUE(viewer.client->send(*message).ok());
    // The still frame after the settings carries a token with all of it.
    EXPECT_TRUE(readUntil(viewer, [](const v1::ServerMessage& m) {
      return m.has_frame() && m.frame().still() && m.frame().input_sequence() >= 1 && !m.frame().resume_token().empty();
    }));
    return viewer;
  }

  // The welcome after a reconnect restored everything connectViewer set.
  void expectResumedIntact(const Viewer& viewer, const v1::Welcome& welcome, int i) {
    EXPECT_TRUE(welcome.resumed()) << i;
    EXPECT_FLOAT_EQ(welcome.camera().eye().x(), viewer.eye.x) << i;
    EXPECT_FLOAT_EQ(welcome.camera().fov_degrees(), 40.0f) << i;
    EXPECT_DOUBLE_EQ(welcome.scene_time_ms(), viewer.sceneMs) << i;
    EXPECT_FALSE(welcome.playing()) << i;
    EXPECT_EQ(welcome.settings().still_samples(), i % 2 == 0 ? 2u : 8u) << i;
    EXPECT_EQ(welcome.settings().jpeg_quality(), static_cast<std::uint32_t>(50 + i)) << i;
  }

  std::unique_ptr<app::LoopbackCluster> cluster_;
};

TEST_F(ScaleOut, SessionsSpreadEvenlyAndSurviveLosingTheirInstance) {
  std::vector<Viewer> viewers;
  for (int i = 0; i < kSessions; ++i) viewers.push_back(connectViewer(i));
  // Least connections: 12 sessions over 3 instances, within one of even.
  std::map<std::string, int> perInstance;
  for (const Viewer& viewer : viewers) ++perInstance[pidOf(viewer.instance)];
  for (std::size_t i = 0; i < cluster_->instances(); ++i) {
    const std::optional<int> sessions = cluster_->sessions(i);
    ASSERT_TRUE(sessions) << "instance " << i << " answers its /metrics";
    EXPECT_NEAR(*sessions, kSessions / kInstances, 1) << "instance " << i;
    EXPECT_EQ(perInstance[std::to_string(cluster_->instancePid(i))], *sessions)
        << "Welcome.instance names the serving process";
  }

  // Instance 0 dies with its sessions open; HAProxy cuts their tunnels, they reconnect and resume.
  const std::string dead = std::to_string(cluster_->instancePid(0));
  cluster_->kill(0);
  for (int i = 0; i < kSessions; ++i) {
    Viewer& viewer = viewers[static_cast<std::size_t>(i)];
    if (pidOf(viewer.instance) != dead) continue;
    const std::optional<v1::Welcome> welcome = welcomeAfterReconnect(viewer);
    ASSERT_TRUE(welcome) << "viewer " << i
                         << " came back; notices: " << (viewer.notices->empty() ? "" : viewer.notices->back());
    expectResumedIntact(viewer, *welcome, i);
    EXPECT_NE(pidOf(viewer.instance), dead);
    EXPECT_TRUE(readUntil(viewer, [](const v1::ServerMessage& m) { return m.has_frame(); })) << "and streams again";
    EXPECT_GE(viewer.client->reconnects(), 1);
  }
  // The others never noticed: no reconnect, no error, and they still answer input.
  for (int i = 0; i < kSessions; ++i) {
    Viewer& viewer = viewers[static_cast<std::size_t>(i)];
    v1::ClientMessage camera;
    *camera.mutable_camera() = protocol::cameraUpdate(viewer.eye + glm::vec3(0.0f, 0.1f, 0.0f), glm::vec3(0.0f),
                                                      glm::vec3(0.0f, 1.0f, 0.0f), 40.0f);
    camera.mutable_camera()->set_sequence(2);
    ASSERT_TRUE(viewer.client->send(camera).ok());
    EXPECT_TRUE(readUntil(viewer, [](const v1::ServerMessage& m) {
      return m.has_frame() && m.frame().input_sequence() == 2;
    })) << i;
    EXPECT_TRUE(viewer.errors.empty()) << i << ": " << (viewer.errors.empty() ? "" : viewer.errors.front());
  }
  EXPECT_EQ(cluster_->sessions(1).value_or(0) + cluster_->sessions(2).value_or(0), kSessions)
      << "all twelve on the two left";

  // Instance 1 drains: at once it stops taking sessions (a new one goes to instance 2), and after
  // --drain-seconds it closes its own with 1001; they resume on instance 2 and it exits 0.
  const std::string draining = std::to_string(cluster_->instancePid(1));
  std::vector<std::size_t> noticesBefore;
  for (const Viewer& viewer : viewers) noticesBefore.push_back(viewer.notices->size());
  cluster_->terminate(1);
  ASSERT_TRUE(cluster_->waitForUp(1, 10s)) << "HAProxy sees instance 1 down once /readyz says draining";
  auto ready = app::httpGet(cluster_->instancePort(1), "/readyz");
  ASSERT_TRUE(ready) << ready.error();
  EXPECT_EQ(ready->first, 503);
  EXPECT_EQ(ready->second, "draining\n");
  Viewer late = connectViewer(kSessions);
  EXPECT_EQ(pidOf(late.instance), std::to_string(cluster_->instancePid(2)))
      << "a new session goes to the instance still up";
  for (int i = 0; i < kSessions; ++i) {
    Viewer& viewer = viewers[static_cast<std::size_t>(i)];
    if (pidOf(viewer.instance) != draining) continue;
    const std::optional<v1::Welcome> welcome = welcomeAfterReconnect(viewer);
    ASSERT_TRUE(welcome) << "viewer " << i << " moved when instance 1 closed it";
    expectResumedIntact(viewer, *welcome, i);
    EXPECT_EQ(pidOf(viewer.instance), std::to_string(cluster_->instancePid(2)));
    ASSERT_GT(viewer.notices->size(), noticesBefore[static_cast<std::size_t>(i)]);
    const std::string& notice = (*viewer.notices)[noticesBefore[static_cast<std::size_t>(i)]];
    EXPECT_NE(notice.find("close 1001"), std::string::npos) << notice;
  }
  EXPECT_EQ(cluster_->instance(1).waitExit(15s), std::optional<int>(0)) << cluster_->instance(1).output();
  EXPECT_EQ(cluster_->sessions(2).value_or(0), kSessions + 1);
}

// Through the front, a token that was altered, signed under another secret or expired gives a fresh
// session and a RESUME_REFUSED error naming why; the server carries on.
TEST_F(ScaleOut, ForgedTokensGetAFreshSessionAndAReason) {
  Viewer viewer = connectViewer(0);
  const std::string token = viewer.client->resumeToken();
  ASSERT_TRUE(token.starts_with("s1."));
  std::string altered = token;
  altered[5] = altered[5] == 'A' ? 'B' : 'A';
  for (const std::string& forged :
       {altered, std::string("s1.") + base64UrlEncode("not a state") + "." + base64UrlEncode(std::string(32, 'x'))}) {
    auto client =
        client::SpeculaClient::connect({"127.0.0.1", cluster_->frontPort(), ""}, protocol::Encoding::Json, 5s);
    ASSERT_TRUE(client) << client.error();
    v1::ClientMessage message;
    *message.mutable_hello() = hello();
    message.mutable_hello()->set_resume_token(forged);
    ASSERT_TRUE((*client)->send(message).ok());
    bool fresh = false, refused = false;
    for (int n = 0; n < 20 && !(fresh && refused); ++n) {
      auto reply = (*client)->receive(10s);
      ASSERT_TRUE(reply) << reply.error();
      if (reply->has_welcome()) fresh = !reply->welcome().resumed();
      if (reply->has_error())
        refused = reply->error().code() == v1::Error::RESUME_REFUSED &&
                  reply->error().message().find("signature does not match") != std::string::npos;
    }
    EXPECT_TRUE(fresh && refused);
  }
}

}  // namespace
}  // namespace specula::testing
