#pragma once
// A real HTTP + WebSocket server on loopback with a fake renderer, and helpers for real clients.
// The fake paints each frame one colour computed from the camera eye, so tests can tell views apart
// without GL; it can also paint noise (large JPEGs) and take a set time per frame.
#include <gtest/gtest.h>

#include <atomic>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "CameraConversions.h"
#include "SpeculaClient.h"
#include "net/HttpServer.h"
#include "scene/builtin/BuiltinScenes.h"
#include "session/SessionHub.h"

namespace specula::testing {

using namespace std::chrono_literals;

struct FakeRendererOptions {
  std::chrono::milliseconds delay{0};
  bool noise = false;
};

class FakeRenderer : public session::FrameRenderer {
 public:
  FakeRenderer(FakeRendererOptions options, std::atomic<int>& renders) : options_(options), renders_(renders) {}
  Result<session::RenderOutput> render(const session::RenderJob& job) override {
    ++renders_;
    std::this_thread::sleep_for(options_.delay);
    session::RenderOutput out;
    out.width = job.width;
    out.height = job.height;
    out.rgba.resize(static_cast<std::size_t>(job.width) * static_cast<std::size_t>(job.height) * 4);
    if (options_.noise) {
      for (auto& byte : out.rgba) byte = static_cast<std::uint8_t>(noise_());
    } else {
      const std::uint8_t grey = eyeColour(job.pose.camera.eye);
      std::fill(out.rgba.begin(), out.rgba.end(), grey);
    }
    out.stageMs = {{"fake", 0.5}};
    if (job.samples > 1) out.stageMs.emplace_back("anti-aliasing", 0.1);  // as the GL renderer reports it
    out.renderMs = static_cast<double>(options_.delay.count());
    out.search.set_searched(42);
    return out;
  }
  // The grey level a frame has for a camera eye (JPEG keeps a flat colour within ±2).
  static std::uint8_t eyeColour(const glm::vec3& eye) {
    return static_cast<std::uint8_t>(std::clamp(128.0f + 20.0f * eye.x, 0.0f, 255.0f));
  }

 private:
  FakeRendererOptions options_;
  std::atomic<int>& renders_;
  std::minstd_rand noise_{7};
};

struct RigOptions {
  session::HubOptions hub;
  net::ServerOptions server;
  FakeRendererOptions renderer;
  std::string bind = "127.0.0.1";
  std::vector<std::string> sceneNotes;  // as a loader would leave them on the scene
};

inline RigOptions defaultRigOptions() {
  RigOptions options;
  options.server.port = 0;
  options.server.writeTimeout = 500ms;
  options.server.handshakeTimeout = 1000ms;
  options.server.firstMessageTimeout = 1000ms;
  options.hub.stillDelay = 100ms;
  options.hub.resumeCapacity = 64;
  return options;
}

class ServerRig {
 public:
  explicit ServerRig(RigOptions options = defaultRigOptions(), const char* sceneName = "checker-sphere") {
    scene::Scene scene = *scene::makeBuiltinScene(sceneName);
    scene.notes = options.sceneNotes;
    scene_ = std::make_shared<const scene::Scene>(std::move(scene));
    auto factory = [this, renderer = options.renderer]() -> Result<std::unique_ptr<session::FrameRenderer>> {
      return std::unique_ptr<session::FrameRenderer>(new FakeRenderer(renderer, renders));
    };
    auto hub = session::SessionHub::start(scene_, options.hub, factory);
    EXPECT_TRUE(hub.ok());
    hub_ = std::move(*hub);
    options.server.metricsText = [hub = hub_.get()] { return hub->prometheusText(); };
    options.server.notReady = [hub = hub_.get()] { return hub->notReady(); };
    auto server = net::HttpServer::start(options.server, *hub_);
    if (!server) ADD_FAILURE() << server.error();
    else server_ = std::move(*server);
  }
  ~ServerRig() { stop(); }

  void stop() {
    if (server_) server_->shutdown(500ms);
    if (hub_) hub_->stop();
    server_.reset();
    hub_.reset();
  }

  std::uint16_t port() const { return server_->port(); }
  session::SessionHub& hub() { return *hub_; }
  net::HttpServer& server() { return *server_; }
  const scene::Scene& scene() const { return *scene_; }

  std::unique_ptr<client::SpeculaClient> connect(protocol::Encoding encoding = protocol::Encoding::Proto,
                                                 const std::string& token = "") {
    auto client = client::SpeculaClient::connect({"127.0.0.1", port(), token}, encoding, 2s);
    EXPECT_TRUE(client.ok()) << (client.ok() ? "" : client.error());
    return client.ok() ? std::move(*client) : nullptr;
  }

  std::atomic<int> renders{0};

 private:
  std::shared_ptr<const scene::Scene> scene_;
  std::unique_ptr<session::SessionHub> hub_;
  std::unique_ptr<net::HttpServer> server_;
};

inline v1::ClientMessage helloMessage(std::uint32_t width = 64, std::uint32_t height = 48,
                                      const std::string& resumeToken = "") {
  v1::ClientMessage message;
  v1::Hello& hello = *message.mutable_hello();
  hello.set_protocol_version(1);
  hello.set_width(width);
  hello.set_height(height);
  hello.set_resume_token(resumeToken);
  return message;
}

inline v1::ClientMessage cameraMessage(glm::vec3 eye, std::uint64_t sequence) {
  v1::ClientMessage message;
  v1::CameraUpdate& camera = *message.mutable_camera() =
      protocol::cameraUpdate(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 45.0f);
  camera.set_sequence(sequence);
  camera.set_client_time_ms(client::steadyMilliseconds());
  return message;
}

inline v1::ClientMessage animationMessage(v1::AnimationControl::Action action, double timeMs = 0.0) {
  v1::ClientMessage message;
  message.mutable_animation()->set_action(action);
  message.mutable_animation()->set_time_ms(timeMs);
  return message;
}

// Reads messages until one satisfies `accept`; fails the test on timeout or close.
inline std::optional<v1::ServerMessage> receiveUntil(client::SpeculaClient& client,
                                                     const std::function<bool(const v1::ServerMessage&)>& accept,
                                                     std::chrono::milliseconds timeout = 3s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    auto message = client.receive(
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
    if (!message) break;
    if (accept(*message)) return *message;
  }
  return std::nullopt;
}

inline bool isFrame(const v1::ServerMessage& message) { return message.has_frame(); }

// Connects and says hello; returns the welcome.
inline v1::Welcome greet(client::SpeculaClient& client, std::uint32_t width = 64, std::uint32_t height = 48,
                         const std::string& resumeToken = "") {
  EXPECT_TRUE(client.send(helloMessage(width, height, resumeToken)).ok());
  auto welcome = receiveUntil(client, [](const v1::ServerMessage& m) { return m.has_welcome(); });
  EXPECT_TRUE(welcome.has_value()) << "no welcome";
  return welcome ? welcome->welcome() : v1::Welcome{};
}

// Waits for the connection to close and returns the close code (0: dropped, -1: still open).
inline int closeCodeAfter(client::SpeculaClient& client, std::chrono::milliseconds timeout = 3s) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!client.closeInfo() && std::chrono::steady_clock::now() < deadline)
    (void)client.receive(
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
  return client.closeInfo() ? client.closeInfo()->code : -1;
}

struct HttpReply {
  int status = 0;
  std::string body;
};

// One HTTP/1.1 request on a fresh connection, with a 3 s limit.
inline HttpReply httpRequest(std::uint16_t port, const std::string& target,
                             boost::beast::http::verb verb = boost::beast::http::verb::get) {
  namespace beast = boost::beast;
  boost::asio::io_context io;
  beast::tcp_stream stream(io);
  HttpReply reply;
  beast::flat_buffer buffer;
  beast::http::request<beast::http::empty_body> request{verb, target, 11};
  request.set(beast::http::field::host, "127.0.0.1");
  beast::http::response<beast::http::string_body> response;
  stream.expires_after(3s);
  stream.async_connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port),
                       [&](beast::error_code error) {
                         if (error) return;
                         beast::http::async_write(stream, request, [&](beast::error_code e, std::size_t) {
                           if (e) return;
                           beast::http::async_read(stream, buffer, response, [&](beast::error_code r, std::size_t) {
                             if (!r) reply = {static_cast<int>(response.result_int()), response.body()};
                           });
                         });
                       });
  io.run_for(4s);
  return reply;
}

// Resident set size of this process in KiB.
inline long residentKiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return 0;
}

}  // namespace specula::testing
