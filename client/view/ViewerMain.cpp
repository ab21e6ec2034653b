// specula-view: the native thin client. A GLFW window shows the stream (frames decoded with TurboJPEG
// into a texture); mouse and keys steer the camera like the browser client; the window title and a
// once-a-second line on stdout show fps, latency, server timings and search/tessellation statistics.
#include <GLFW/glfw3.h>
#include <turbojpeg.h>

#include <atomic>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iostream>
#include <mutex>
#include <map>
#include <optional>
#include <thread>

#include "ConnectionOptions.h"
#include "LoadRun.h"
#include "OrbitCamera.h"
#include "ResumingClient.h"
#include "base/CommandLine.h"
#include "encode/PngEncoder.h"

namespace {

using namespace specula;
using Clock = std::chrono::steady_clock;

int fail(const std::string& message) {
  std::cerr << "specula-view: " << message << "\n";
  return 1;
}

// The network thread owns the client; the window thread talks to it only through this.
struct Link {
  std::mutex mutex;
  std::optional<v1::Frame> latestFrame;  // latest wins
  std::optional<v1::Welcome> welcome;
  std::deque<v1::ClientMessage> outgoing;
  std::string problem;
  std::atomic<bool> stop{false};
  std::uint64_t framesReceived = 0;
};

void runNetwork(client::ResumingClient& client, Link& link) {
  while (!link.stop) {
    std::deque<v1::ClientMessage> outgoing;
    {
      std::lock_guard lock(link.mutex);
      outgoing.swap(link.outgoing);
    }
    for (const v1::ClientMessage& message : outgoing)
      if (Status sent = client.send(message); !sent) {
        std::lock_guard lock(link.mutex);
        link.problem = sent.error();
      }
    auto message = client.receive(std::chrono::milliseconds(5));
    std::lock_guard lock(link.mutex);
    if (!message) {
      if (client.closeInfo()) {
        link.problem = "the server closed the connection: " + std::to_string(client.closeInfo()->code) + " " +
                       client.closeInfo()->reason;
        return;
      }
      continue;
    }
    if (message->has_welcome()) link.welcome = message->welcome();
    if (message->has_error() && message->error().code() == v1::Error::RESUME_REFUSED) std::printf("specula-view: %s\n", message->error().message().c_str());
    else if (message->has_error()) link.problem = "server: " + message->error().message();
    if (message->has_frame()) {
      link.latestFrame = std::move(*message->mutable_frame());
      ++link.framesReceived;
    }
  }
}

struct Viewer {
  explicit Viewer(Link& l) : link(l) {}
  Link& link;
  std::optional<client::OrbitCamera> camera;
  bool steering = false;  // the user moved the camera: stop following the scene's
  bool dragging = false, panning = false;
  double lastX = 0, lastY = 0;
  std::uint64_t sequence = 0;
  std::map<std::uint64_t, double> sentAt;
  bool playing = true;

  void send(v1::ClientMessage message) {
    std::lock_guard lock(link.mutex);
    link.outgoing.push_back(std::move(message));
  }
  void moveCamera() {
    if (!camera) return;
    steering = true;
    const double now = client::steadyMilliseconds();
    sentAt[++sequence] = now;
    send(camera->message(sequence, now));
  }
};

Viewer* viewerOf(GLFWwindow* window) { return static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

}  // namespace

int main(int argc, char** argv) {
  std::vector<OptionSpec> specs = client::connectionOptions();
  for (OptionSpec spec : std::initializer_list<OptionSpec>{
           {"size", "WxH", "window size", "960x540"},
           {"frames", "N", "exit after drawing N frames (0: never)", "0"},
           {"seconds", "S", "exit after S seconds (0: never)", "0"},
           {"screenshot", "FILE.png", "on exit, save what the window showed last", ""},
       })
    specs.push_back(spec);
  CommandLine options(
      "specula-view [--url ws://HOST:PORT] [--size WxH] [--frames N] [--seconds S]",
      "Opens a window on a Specula server's stream. Drag: orbit; right-drag or shift-drag: pan; wheel: zoom;\n"
      "arrows: orbit; +/-: zoom; space: play/pause; Esc: quit. Statistics are in the window title and printed\n"
      "once a second. --frames or --seconds end the run (scripts, tests).",
      std::move(specs));
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (auto exitCode = options.parseOrExit(arguments, fail)) return *exitCode;
  auto connection = client::parseConnectionOptions(options);
  auto size = options.size("size", 8192);
  auto frameLimit = options.integer("frames", 0, 1 << 30);
  auto seconds = options.number("seconds");
  if (!connection) return fail(connection.error());
  if (!size) return fail(size.error());
  if (!frameLimit) return fail(frameLimit.error());
  if (!seconds || *seconds < 0.0) return fail("--seconds expects a number >= 0");

  // A lost connection is retried and the session resumed (camera, animation, settings); said on stdout.
  v1::Hello hello;
  hello.set_protocol_version(1);
  hello.set_width(static_cast<std::uint32_t>(size->first));
  hello.set_height(static_cast<std::uint32_t>(size->second));
  auto connected = client::ResumingClient::connect(connection->address, connection->encoding, hello, connection->reconnect,
                                                   [](const std::string& notice) {
                                                     std::printf("specula-view: %s\n", notice.c_str());
                                                     std::fflush(stdout);
                                                   });
  if (!connected) return fail(connected.error());
  if (!glfwInit()) return fail("cannot open a window: no display (set DISPLAY, or run under xvfb-run)");
  GLFWwindow* window = glfwCreateWindow(size->first, size->second, "Specula", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return fail("cannot create an OpenGL window on this display");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  using GenFramebuffers = void (*)(GLsizei, GLuint*);
  using BindFramebuffer = void (*)(GLenum, GLuint);
  using FramebufferTexture2D = void (*)(GLenum, GLenum, GLenum, GLuint, GLint);
  using BlitFramebuffer = void (*)(GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum);
  auto genFramebuffers = reinterpret_cast<GenFramebuffers>(glfwGetProcAddress("glGenFramebuffers"));
  auto bindFramebuffer = reinterpret_cast<BindFramebuffer>(glfwGetProcAddress("glBindFramebuffer"));
  auto framebufferTexture2D = reinterpret_cast<FramebufferTexture2D>(glfwGetProcAddress("glFramebufferTexture2D"));
  auto blitFramebuffer = reinterpret_cast<BlitFramebuffer>(glfwGetProcAddress("glBlitFramebuffer"));
  if (!genFramebuffers || !bindFramebuffer || !framebufferTexture2D || !blitFramebuffer)
    return fail("this OpenGL lacks framebuffer blits (OpenGL 3.0 is needed)");

  Link link;
  Viewer viewer(link);
  glfwSetWindowUserPointer(window, &viewer);
  int framebufferWidth = 0, framebufferHeight = 0;
  glfwGetFramebufferSize(window, &framebufferWidth, &framebufferHeight);
  if (framebufferWidth != size->first || framebufferHeight != size->second) {  // a HiDPI window has more pixels than asked for
    v1::ClientMessage resize;
    resize.mutable_resize()->set_width(static_cast<std::uint32_t>(std::max(1, framebufferWidth)));
    resize.mutable_resize()->set_height(static_cast<std::uint32_t>(std::max(1, framebufferHeight)));
    viewer.send(resize);
  }
  std::thread network([&] { runNetwork(**connected, link); });

  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
    Viewer& v = *viewerOf(w);
    v.dragging = action == GLFW_PRESS;
    v.panning = button == GLFW_MOUSE_BUTTON_RIGHT || (mods & GLFW_MOD_SHIFT);
    glfwGetCursorPos(w, &v.lastX, &v.lastY);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    Viewer& v = *viewerOf(w);
    if (!v.dragging || !v.camera) return;
    const float dx = static_cast<float>(x - v.lastX), dy = static_cast<float>(y - v.lastY);
    v.lastX = x;
    v.lastY = y;
    int width = 0, height = 0;
    glfwGetWindowSize(w, &width, &height);
    const float perPixel = 2.0f * v.camera->radius * std::tan(glm::radians(v.camera->fovDegrees) / 2.0f) /
                           static_cast<float>(std::max(1, height));
    if (v.panning) v.camera->pan(-dx * perPixel, dy * perPixel);
    else v.camera->orbit(-dx * 0.008f, dy * 0.008f);
    v.moveCamera();
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    Viewer& v = *viewerOf(w);
    if (!v.camera) return;
    v.camera->zoom(std::exp(static_cast<float>(-dy) * 0.1f));
    v.moveCamera();
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_RELEASE) return;
    Viewer& v = *viewerOf(w);
    if (key == GLFW_KEY_ESCAPE) return glfwSetWindowShouldClose(w, 1);
    if (key == GLFW_KEY_SPACE) {
      v.playing = !v.playing;
      v1::ClientMessage message;
      message.mutable_animation()->set_action(v.playing ? v1::AnimationControl::PLAY : v1::AnimationControl::PAUSE);
      return v.send(message);
    }
    if (!v.camera) return;
    if (key == GLFW_KEY_LEFT) v.camera->orbit(-0.1f, 0.0f);
    else if (key == GLFW_KEY_RIGHT) v.camera->orbit(0.1f, 0.0f);
    else if (key == GLFW_KEY_UP) v.camera->orbit(0.0f, 0.1f);
    else if (key == GLFW_KEY_DOWN) v.camera->orbit(0.0f, -0.1f);
    else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD) v.camera->zoom(0.9f);
    else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) v.camera->zoom(1.1f);
    else return;
    v.moveCamera();
  });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int width, int height) {
    if (width < 1 || height < 1) return;
    v1::ClientMessage message;
    message.mutable_resize()->set_width(static_cast<std::uint32_t>(width));
    message.mutable_resize()->set_height(static_cast<std::uint32_t>(height));
    viewerOf(w)->send(message);
  });

  GLuint texture = 0, framebuffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  genFramebuffers(1, &framebuffer);
  tjhandle decoder = tjInitDecompress();
  std::vector<unsigned char> pixels;
  int textureWidth = 0, textureHeight = 0;
  std::uint64_t drawn = 0, framesThisSecond = 0;
  double latencyMs = 0.0;
  std::optional<v1::Frame> shown;
  // The last frame, stretched over the window; frame row 0 is the top, so it is blitted upside down.
  auto drawWindow = [&] {
    glfwGetFramebufferSize(window, &framebufferWidth, &framebufferHeight);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (textureWidth == 0) return;
    bindFramebuffer(0x8CA8 /* GL_READ_FRAMEBUFFER */, framebuffer);
    framebufferTexture2D(0x8CA8, 0x8CE0 /* GL_COLOR_ATTACHMENT0 */, GL_TEXTURE_2D, texture, 0);
    blitFramebuffer(0, 0, textureWidth, textureHeight, 0, framebufferHeight, framebufferWidth, 0, GL_COLOR_BUFFER_BIT,
                    GL_LINEAR);
    bindFramebuffer(0x8CA8, 0);
  };
  const Clock::time_point start = Clock::now();
  Clock::time_point secondStart = start;
  std::string problem;
  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    std::optional<v1::Frame> frame;
    {
      std::lock_guard lock(link.mutex);
      frame.swap(link.latestFrame);
      problem = link.problem;
    }
    if (!problem.empty()) break;
    if (frame) {
      int width = 0, height = 0, subsampling = 0, colourspace = 0;
      const auto* bytes = reinterpret_cast<const unsigned char*>(frame->jpeg().data());
      const auto length = static_cast<unsigned long>(frame->jpeg().size());
      if (tjDecompressHeader3(decoder, bytes, length, &width, &height, &subsampling, &colourspace) == 0) {
        pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        if (tjDecompress2(decoder, bytes, length, pixels.data(), width, 0, height, TJPF_RGBA, 0) == 0) {
          glBindTexture(GL_TEXTURE_2D, texture);
          glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
          textureWidth = width;
          textureHeight = height;
          ++drawn;
          ++framesThisSecond;
          if (auto sent = viewer.sentAt.find(frame->input_sequence()); sent != viewer.sentAt.end()) {
            latencyMs = client::steadyMilliseconds() - sent->second;
            viewer.sentAt.erase(viewer.sentAt.begin(), std::next(sent));
          }
          if (!viewer.steering && frame->has_camera()) viewer.camera = client::OrbitCamera::from(frame->camera());
          shown = std::move(frame);
        }
      }
    }
    drawWindow();
    glfwSwapBuffers(window);

    const Clock::time_point now = Clock::now();
    if (now - secondStart >= std::chrono::seconds(1) && shown) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "Specula  %ux%u  %llu fps  input->frame %.0f ms  render %.1f ms  encode %.1f ms  search %u vertices "
                    "%.2f steps  tessellation %u->%u",
                    shown->width(), shown->height(), static_cast<unsigned long long>(framesThisSecond), latencyMs,
                    shown->render_ms(), shown->encode_ms(), shown->search().searched(), shown->search().mean_steps(),
                    shown->tessellation().input_triangles(), shown->tessellation().finished_triangles());
      glfwSetWindowTitle(window, line);
      std::printf("%s\n", line);
      std::fflush(stdout);
      framesThisSecond = 0;
      secondStart = now;
    }
    if (*frameLimit > 0 && drawn >= static_cast<std::uint64_t>(*frameLimit)) break;
    if (*seconds > 0.0 && now - start >= std::chrono::duration<double>(*seconds)) break;
  }
  if (options.has("screenshot")) {  // the window as drawn, read back before it closes
    drawWindow();  // the back buffer: after a swap its contents are undefined
    std::vector<std::uint8_t> shot(static_cast<std::size_t>(framebufferWidth) * static_cast<std::size_t>(framebufferHeight) * 4);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, framebufferWidth, framebufferHeight, GL_RGBA, GL_UNSIGNED_BYTE, shot.data());
    std::vector<std::uint8_t> topDown(shot.size());
    const std::size_t row = static_cast<std::size_t>(framebufferWidth) * 4;
    for (int y = 0; y < framebufferHeight; ++y)
      std::copy_n(shot.data() + static_cast<std::size_t>(framebufferHeight - 1 - y) * row, row, topDown.data() + static_cast<std::size_t>(y) * row);
    auto png = encode::encodePng({topDown.data(), framebufferWidth, framebufferHeight});
    std::ofstream file(options.text("screenshot"), std::ios::binary | std::ios::trunc);
    if (png) file.write(reinterpret_cast<const char*>(png->data()), static_cast<std::streamsize>(png->size()));
    if (!png || !file) problem = "could not write the screenshot '" + options.text("screenshot") + "'";
  }
  link.stop = true;
  network.join();
  (*connected)->close();
  tjDestroy(decoder);
  glfwDestroyWindow(window);
  glfwTerminate();
  std::printf("specula-view: drew %llu frames (%llu received)\n", static_cast<unsigned long long>(drawn),
              static_cast<unsigned long long>(link.framesReceived));
  if (!problem.empty()) return fail(problem);
  return 0;
}
