// `specula serve` as users run it: a real process with the GL renderer (software GL is fine), real
// clients, real signals.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <turbojpeg.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "SpeculaClient.h"

namespace specula::testing {
namespace {

using namespace std::chrono_literals;

// A child process with stdout and stderr captured into one pipe.
class Process {
 public:
  explicit Process(std::vector<std::string> arguments) {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(fds[1], STDOUT_FILENO);
      dup2(fds[1], STDERR_FILENO);
      close(fds[0]);
      std::vector<char*> argv;
      for (std::string& argument : arguments) argv.push_back(argument.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(fds[1]);
    output_ = fds[0];
  }
  ~Process() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (output_ >= 0) close(output_);
  }
  pid_t pid() const { return pid_; }

  // Reads output until `pattern` matches it; returns the match or an empty match on timeout/exit.
  std::smatch waitFor(const std::regex& pattern, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::smatch match;
    while (!std::regex_search(text_, match, pattern)) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left <= 0ms || !readSome(left)) return {};
    }
    return match;
  }
  // Waits for exit; returns the exit status, or -1 on timeout or a signal.
  int waitExit(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        while (readSome(10ms)) {}
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      readSome(20ms);
    }
    return -1;
  }
  const std::string& output() const { return text_; }

 private:
  bool readSome(std::chrono::milliseconds timeout) {
    pollfd fd{output_, POLLIN, 0};
    if (poll(&fd, 1, static_cast<int>(timeout.count())) <= 0) return false;
    char buffer[4096];
    const ssize_t count = read(output_, buffer, sizeof buffer);
    if (count <= 0) return false;
    text_.append(buffer, static_cast<std::size_t>(count));
    return true;
  }

  pid_t pid_ = -1;
  int output_ = -1;
  bool exited_ = false;
  std::string text_;
};

// Standard deviation of a frame's grey levels: 0 for a blank frame.
double greyDeviation(const v1::Frame& frame) {
  tjhandle handle = tjInitDecompress();
  const int width = static_cast<int>(frame.width()), height = static_cast<int>(frame.height());
  std::vector<unsigned char> grey(static_cast<std::size_t>(width * height));
  const int failed = tjDecompress2(handle, reinterpret_cast<const unsigned char*>(frame.jpeg().data()),
                                   static_cast<unsigned long>(frame.jpeg().size()), grey.data(), width, 0, height,
                                   TJPF_GRAY, 0);
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
std::unique_ptr<client::SpeculaClient> greetedClient(std::uint16_t port, net::Encoding encoding, std::uint32_t width,
                                                     std::uint32_t height) {
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

TEST(ServeProcess, StreamsRealFramesAndSigtermClosesEveryClientWithGoingAwayWithinASecond) {
  Process server({SPECULA_BINARY, "serve", "--port", "0", "--scene", "quad"});
  const std::smatch listening = server.waitFor(std::regex("listening on 127\\.0\\.0\\.1:(\\d+)"), 120s);
  ASSERT_FALSE(listening.empty()) << server.output();
  const auto port = static_cast<std::uint16_t>(std::stoi(listening[1]));

  std::vector<std::unique_ptr<client::SpeculaClient>> clients;
  for (net::Encoding encoding : {net::Encoding::Proto, net::Encoding::Json}) {
    auto client = greetedClient(port, encoding, 160, 120);
    ASSERT_TRUE(client);
    std::optional<v1::Frame> frame;
    for (int i = 0; i < 10 && !frame; ++i) {
      auto message = client->receive(60s);
      ASSERT_TRUE(message) << message.error() << "\n" << server.output();
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
  ASSERT_EQ(kill(server.pid(), SIGTERM), 0);
  for (auto& client : clients) {
    while (!client->closeInfo() && std::chrono::steady_clock::now() - start < 1s) (void)client->receive(100ms);
    ASSERT_TRUE(client->closeInfo()) << "closed within 1 s of SIGTERM";
    EXPECT_EQ(client->closeInfo()->code, 1001);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
  EXPECT_EQ(server.waitExit(5s), 0) << server.output();
}

// Every search option `serve --help` lists as a sessions' default reaches a new session.
TEST(ServeProcess, SearchOptionsBecomeEverySessionsDefaults) {
  Process server({SPECULA_BINARY, "serve", "--port", "0", "--scene", "quad", "--search", "explosion-map", "--explosion-refine",
                  "on", "--explosion-map-size", "128", "--virtual-pixels", "as-placed", "--extrusions", "search",
                  "--still-samples", "16", "--interactive-samples", "2"});
  const std::smatch listening = server.waitFor(std::regex("listening on 127\\.0\\.0\\.1:(\\d+)"), 120s);
  ASSERT_FALSE(listening.empty()) << server.output();
  auto client = greetedClient(static_cast<std::uint16_t>(std::stoi(listening[1])), net::Encoding::Proto, 64, 48);
  ASSERT_TRUE(client);
  std::optional<v1::Welcome> welcome;
  for (int i = 0; i < 10 && !welcome; ++i) {
    auto message = client->receive(60s);
    ASSERT_TRUE(message) << message.error() << "\n" << server.output();
    if (message->has_welcome()) welcome = message->welcome();
  }
  ASSERT_TRUE(welcome);
  EXPECT_EQ(welcome->settings().search(), v1::SEARCH_EXPLOSION_MAP_REFINED);
  EXPECT_EQ(welcome->settings().explosion_map_size(), 128u);
  EXPECT_EQ(welcome->settings().virtual_pixels(), v1::PIXELS_AS_PLACED);
  EXPECT_EQ(welcome->settings().extrusions(), v1::EXTRUSIONS_SEARCH);
  EXPECT_EQ(welcome->settings().still_samples(), 16u);
  EXPECT_EQ(welcome->settings().interactive_samples(), 2u);
}

TEST(ServeProcess, RefusesASampleCountWithoutAPattern) {
  Process server({SPECULA_BINARY, "serve", "--port", "0", "--still-samples", "6"});
  EXPECT_EQ(server.waitExit(30s), 1);
  EXPECT_NE(server.output().find("--still-samples: samples per pixel must be 1, 2, 4, 8 or 16, got 6"), std::string::npos) << server.output();
}

TEST(ServeProcess, RefusesANonLoopbackBindWithoutAToken) {
  Process server({SPECULA_BINARY, "serve", "--bind", "0.0.0.0", "--port", "0"});
  EXPECT_EQ(server.waitExit(30s), 1);
  EXPECT_NE(server.output().find("--token"), std::string::npos) << server.output();
}

TEST(ServeProcess, SaysWhenThePortIsTaken) {
  Process first({SPECULA_BINARY, "serve", "--port", "0", "--scene", "quad"});
  const std::smatch listening = first.waitFor(std::regex("listening on 127\\.0\\.0\\.1:(\\d+)"), 120s);
  ASSERT_FALSE(listening.empty()) << first.output();
  Process second({SPECULA_BINARY, "serve", "--port", listening[1].str(), "--scene", "quad"});
  EXPECT_EQ(second.waitExit(120s), 1);
  EXPECT_NE(second.output().find("cannot listen on 127.0.0.1:" + listening[1].str()), std::string::npos)
      << second.output();
}

}  // namespace
}  // namespace specula::testing
