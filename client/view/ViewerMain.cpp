// specula-view: the native thin client. A GLFW window shows the stream (frames decoded with TurboJPEG
// into a texture); mouse and keys steer the camera like the browser client; the window title and a
// once-a-second line on stdout show fps, latency, server timings and search/tessellation statistics.
#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "CameraInput.h"
#include "ServerLink.h"
#include "ViewerLoop.h"
#include "ViewerOptions.h"
#include "ViewerWindow.h"
#include "base/CommandFailure.h"

namespace {

using namespace specula;

constexpr CommandFailure fail{"specula-view"};

}  // namespace

int main(int argc, char** argv) {
  CommandLine commandLine = view::viewerCommandLine();
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (auto exitCode = commandLine.parseOrExit(arguments, fail)) return *exitCode;
  auto options = view::readViewerOptions(commandLine);
  if (!options) return fail(options.error());
  auto client = view::connectToServer(*options);
  if (!client) return fail(client.error());
  auto window = view::ViewerWindow::open(options->size);
  if (!window) return fail(window.error());

  view::Link link;
  view::CameraInput input(link);
  input.listenTo((*window)->handle());
  if (const auto [width, height] = (*window)->framebufferSize(); std::pair(width, height) != options->size)
    input.sendResize(std::max(1, width), std::max(1, height));  // a HiDPI window has more pixels than asked for
  std::thread network([&] { view::runNetwork(**client, link); });
  view::LoopOutcome outcome = view::runViewerLoop(**window, link, input, *options);
  if (options->screenshot)
    if (Status saved = (*window)->saveScreenshot(*options->screenshot); !saved) outcome.problem = saved.error();
  link.stop = true;
  network.join();
  (*client)->close();
  window->reset();
  std::printf("specula-view: drew %llu frames (%llu received)\n", static_cast<unsigned long long>(outcome.drawn),
              static_cast<unsigned long long>(link.framesReceived));
  if (!outcome.problem.empty()) return fail(outcome.problem);
  return 0;
}
