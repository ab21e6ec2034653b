#pragma once
// Mouse and keys steer the camera like the browser client: drag orbits, right- or shift-drag pans, the wheel
// zooms, arrows orbit, +/- zoom, space plays or pauses, Esc quits. Each change is a message to the server.
#include <GLFW/glfw3.h>

#include <cstdint>
#include <map>
#include <optional>

#include "OrbitCamera.h"
#include "ServerLink.h"

namespace specula::view {

class CameraInput {
 public:
  explicit CameraInput(Link& link) : link_(link) {}

  // Takes the window's mouse, key and resize callbacks; this must outlive the window.
  void listenTo(GLFWwindow* window);
  // Asks the server for frames of this size.
  void sendResize(int width, int height);
  // For a frame about to be shown: the time from the input it answers to now, if it answers one; and, until
  // the user steers, the camera follows the frame's.
  std::optional<double> frameShown(const v1::Frame& frame);

 private:
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onCursorPos(GLFWwindow* window, double x, double y);
  static void onScroll(GLFWwindow* window, double dx, double dy);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onFramebufferSize(GLFWwindow* window, int width, int height);

  void send(v1::ClientMessage message);
  void moveCamera();

  Link& link_;
  std::optional<client::OrbitCamera> camera_;
  bool steering_ = false;  // the user moved the camera: stop following the scene's
  bool dragging_ = false, panning_ = false;
  double lastX_ = 0, lastY_ = 0;
  std::uint64_t sequence_ = 0;
  std::map<std::uint64_t, double> sentAt_;  // input sequence → when it was sent
  bool playing_ = true;
};

}  // namespace specula::view
