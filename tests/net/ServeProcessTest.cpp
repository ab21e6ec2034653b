// `specula serve` as users run it: a real process with the GL renderer (software GL is fine), real
// clients, real signals.
#include <gtest/gtest.h>
#include <signal.h>
#include <turbojpeg.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "SpeculaClient.h"
#include "app/ChildProcess.h"

namespace specula::testing {
namespace {

using namespace std::chrono_literals;

// A started `specula serve` (or a failed expectation and null).
std::unique_ptr<app::ChildProcess> serve(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), {SPECULA_BINARY, "serve"});
  auto process = app::ChildProcess::start(std::move(arguments));
  EXPECT_TRUE(process) << process.error();
  return process ? std::move(*process) : nullptr;
}

const std::regex kListening("listening on 127\\.0\\.0\\.1:(\\d+)");

// Standard deviation of a frame's grey levels: 0 for a blank frame.
double greyDeviation(const v1::Frame& frame) {
  tjhandle handle = tjInitDecompress();
  const int width = static_cast<int>(frame.width()), height = static_cast<int>(frame.height());
  std::vector<unsigned char> grey(static_cast<std::size_t>(width * height));
  const int failed =
      tjDecompress2(handle, reinterpret_cast<const unsigned char*>(frame.jpeg().data()),
                    static_cast<unsigned long>(frame.jpeg().size()), grey.data(), width, 0, height, TJPF_GRAY, 0);
  tjDestroy(handle);
  if (failed) return -1.0;
  double sum = 0.0, squares = 0.0;
  for (unsigned char g : grey) {
    sum += g;
    squares += static_cast<double>(g) * g;
  }
  const double mean = sum / static_cast<double>(grey.size());
  return std::sqrt(std::max(0.0, squares / static_cast<double>(grey.size()) - mean * mean));
}

// A client of the server on `port` that has said hello with a `width` × `height` viewport; null (and a
// failed expectation) when it could not.
std::unique_ptr<client::SpeculaClient> greetedClient(std::uint16_t port, protocol::Encoding encoding,
                                                     std::uint32_t width, std::uint32_t height) {
  auto client = client::SpeculaClient::connect({"127.0.0.1", port, ""}, encoding, 5s);
  EXPECT_TRUE(client) << client.error();
  if (!client) return nullptr;
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(1);
  hello.mutable_hello()->set_width(width);
  hello.mutable_hello()->set_height(height);
  EXPECT_TRUE((*client)->send(hello).ok());
  return std::move(*client);
}

TEST(ServeProcessTiming, StreamsRealFramesAndSigtermClosesEveryClientWithGoingAwayWithinASecond) {
  auto server = serve({"--port", "0", "--scene", "quad"});
  ASSERT_TRUE(server);
  const auto listening = server->waitFor(kListening, 120s);
  ASSERT_TRUE(listening) << server->output();
  const auto port = static_cast<std::uint16_t>(std::stoi((*listening)[1]));

  std::vector<std::unique_ptr<client::SpeculaClient>> clients;
  for (protocol::Encoding encoding : {protocol::Encoding::Proto, protocol::Encoding::Json}) {
    auto client = greetedClient(port, encoding, 160, 120);
    ASSERT_TRUE(client);
    std::optional<v1::Frame> frame;
    for (int i = 0; i < 10 && !frame; ++i) {
      auto message = client->receive(60s);
      ASSERT_TRUE(message) << message.error() << "\n" << server->output();
      if (message->has_frame()) frame = message->frame();
    }
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->width(), 160u);
    EXPECT_EQ(frame->height(), 120u);
    EXPECT_GT(greyDeviation(*frame), 5.0) << "a rendered scene, not a blank frame";
    EXPECT_GT(frame->stages_size(), 2) << "per-pass GPU timings";
    ASSERT_EQ(frame->plan_size(), 1) << "the quad's sphere, one part";
    EXPECT_EQ(frame->plan(0).searched_objects(), 1u) << "the plan per mirror part travels with the frame";
    EXPECT_EQ(frame->plan(0).method(), "ray-cast") << "the sphere covers few of 160x120 pixels";
    EXPECT_EQ(frame->search().searched(), 0u) << "a ray-cast mirror searches nothing";
    clients.push_back(std::move(client));
  }

  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(server->pid(), SIGTERM), 0);
  for (auto& client : clients) {
    while (!client->closeInfo() && std::chrono::steady_clock::now() - start < 1s) (void)client->receive(100ms);
    ASSERT_TRUE(client->closeInfo()) << "closed within 1 s of SIGTERM";
    EXPECT_EQ(client->closeInfo()->code, 1001);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
  EXPECT_EQ(server->waitExit(5s), std::optional<int>(0)) << server->output();
}

// Every search option `serve --help` lists as a sessions' default reaches a new session.
TEST(ServeProcess, SearchOptionsBecomeEverySessionsDefaults) {
  auto server = serve({"--port", "0", "--scene", "quad", "--search", "explosion-map", "--explosion-refine", "on",
                       "--explosion-map-size", "128", "--virtual-pixels", "as-placed", "--extrusions", "search",
                       "--still-samples", "16", "--interactive-samples", "2"});
  ASSERT_TRUE(server);
  const auto listening = server->waitFor(kListening, 120s);
  ASSERT_TRUE(listening) << server->output();
  auto client =
      greetedClient(static_cast<std::uint16_t>(std::stoi((*listening)[1])), protocol::Encoding::Proto, 64, 48);
  ASSERT_TRUE(client);
  std::optional<v1::Welcome> welcome;
  for (int i = 0; i < 10 && !welcome; ++i) {
    auto message = client->receive(60s);
    ASSERT_TRUE(message) << message.error() << "\n" << server->output();
    if (message->has_welcome()) welcome = message->welcome();
  }
  ASSERT_TRUE(welcome);
  EXPECT_EQ(welcome->settings().search(), v1::SEARCH_EXPLOSION_MAP);
  EXPECT_EQ(welcome->settings().explosion_refine(), v1::SWITCH_ON);
  EXPECT_EQ(welcome->settings().ray_cast(), v1::RAY_CAST_NEVER) << "the search named is what the sessions run";
  EXPECT_EQ(welcome->settings().explosion_map_size(), 128u);
  EXPECT_EQ(welcome->settings().virtual_pixels(), v1::PIXELS_AS_PLACED);
  EXPECT_EQ(welcome->settings().extrusions(), v1::EXTRUSIONS_SEARCH);
  EXPECT_EQ(welcome->settings().still_samples(), 16u);
  EXPECT_EQ(welcome->settings().interactive_samples(), 2u);
}

TEST(ServeProcess, RefusesASampleCountWithoutAPattern) {
  auto server = serve({"--port", "0", "--still-samples", "6"});
  ASSERT_TRUE(server);
  EXPECT_EQ(server->waitExit(30s), std::optional<int>(1));
  EXPECT_NE(server->output().find("--still-samples expects 1, 2, 4, 8 or 16, got '6'"), std::string::npos)
      << server->output();
}

TEST(ServeProcess, RefusesAMissingOrShortResumeSecretBeforeStarting) {
  auto missing = serve({"--port", "0", "--resume-secret-file", "/nonexistent/resume.secret"});
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->waitExit(30s), std::optional<int>(1));
  EXPECT_NE(missing->output().find("--resume-secret-file: /nonexistent/resume.secret"), std::string::npos)
      << missing->output();
  const std::string shortSecret = ::testing::TempDir() + "short.secret";
  std::ofstream(shortSecret) << "too short\n";
  auto weak = serve({"--port", "0", "--resume-secret-file", shortSecret});
  ASSERT_TRUE(weak);
  EXPECT_EQ(weak->waitExit(30s), std::optional<int>(1));
  EXPECT_NE(weak->output().find("the resume secret has 9 bytes; use at least 32"), std::string::npos) << weak->output();
}

TEST(ServeProcess, RefusesANonLoopbackBindWithoutAToken) {
  auto server = serve({"--bind", "0.0.0.0", "--port", "0"});
  ASSERT_TRUE(server);
  EXPECT_EQ(server->waitExit(30s), std::optional<int>(1));
  EXPECT_NE(server->output().find("--token"), std::string::npos) << server->output();
}

TEST(ServeProcess, SaysWhenThePortIsTaken) {
  auto first = serve({"--port", "0", "--scene", "quad"});
  ASSERT_TRUE(first);
  const auto listening = first->waitFor(kListening, 120s);
  ASSERT_TRUE(listening) << first->output();
  auto second = serve({"--port", (*listening)[1], "--scene", "quad"});
  ASSERT_TRUE(second);
  EXPECT_EQ(second->waitExit(120s), std::optional<int>(1));
  EXPECT_NE(second->output().find("cannot listen on 127.0.0.1:" + (*listening)[1]), std::string::npos)
      << second->output();
}

}  // namespace
}  // namespace specula::testing
