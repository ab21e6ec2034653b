#include "CameraInput.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace specula::view {

namespace {
CameraInput& inputOf(GLFWwindow* window) { return *static_cast<CameraInput*>(glfwGetWindowUserPointer(window)); }
}  // namespace

void CameraInput::listenTo(GLFWwindow* window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursorPos);
  glfwSetScrollCallback(window, onScroll);
  glfwSetKeyCallback(window, onKey);
  glfwSetFramebufferSizeCallback(window, onFramebufferSize);
}

void CameraInput::sendResize(int width, int height) {
  v1::ClientMessage message;
  message.mutable_resize()->set_width(static_cast<std::uint32_t>(width));
  message.mutable_resize()->set_height(static_cast<std::uint32_t>(height));
  send(message);
}

std::optional<double> CameraInput::frameShown(const v1::Frame& frame) {
  std::optional<double> latencyMs;
  if (auto sent = sentAt_.find(frame.input_sequence()); sent != sentAt_.end()) {
    latencyMs = client::steadyMilliseconds() - sent->second;
    sentAt_.erase(sentAt_.begin(), std::next(sent));
  }
  if (!steering_ && frame.has_camera()) camera_ = client::OrbitCamera::from(frame.camera());
  return latencyMs;
}

void CameraInput::send(v1::ClientMessage message) {
  std::lock_guard lock(link_.mutex);
  link_.outgoing.push_back(std::move(message));
}

void CameraInput::moveCamera() {
  if (!camera_) return;
  steering_ = true;
  const double now = client::steadyMilliseconds();
  sentAt_[++sequence_] = now;
  send(camera_->message(sequence_, now));
}

void CameraInput::onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  CameraInput& input = inputOf(window);
  input.dragging_ = action == GLFW_PRESS;
  input.panning_ = button == GLFW_MOUSE_BUTTON_RIGHT || (mods & GLFW_MOD_SHIFT);
  glfwGetCursorPos(window, &input.lastX_, &input.lastY_);
}

void CameraInput::onCursorPos(GLFWwindow* window, double x, double y) {
  CameraInput& input = inputOf(window);
  if (!input.dragging_ || !input.camera_) return;
  const float dx = static_cast<float>(x - input.lastX_), dy = static_cast<float>(y - input.lastY_);
  input.lastX_ = x;
  input.lastY_ = y;
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  client::OrbitCamera& camera = *input.camera_;
  const float perPixel =
      2.0f * camera.radius * std::tan(glm::radians(camera.fovDegrees) / 2.0f) / static_cast<float>(std::max(1, height));
  if (input.panning_) camera.pan(-dx * perPixel, dy * perPixel);
  else camera.orbit(-dx * 0.008f, dy * 0.008f);
  input.moveCamera();
}

void CameraInput::onScroll(GLFWwindow* window, double, double dy) {
  CameraInput& input = inputOf(window);
  if (!input.camera_) return;
  input.camera_->zoom(std::exp(static_cast<float>(-dy) * 0.1f));
  input.moveCamera();
}

void CameraInput::onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_RELEASE) return;
  CameraInput& input = inputOf(window);
  if (key == GLFW_KEY_ESCAPE) return glfwSetWindowShouldClose(window, 1);
  if (key == GLFW_KEY_SPACE) {
    input.playing_ = !input.playing_;
    v1::ClientMessage message;
    message.mutable_animation()->set_action(input.playing_ ? v1::AnimationControl::PLAY : v1::AnimationControl::PAUSE);
    return input.send(message);
  }
  if (!input.camera_) return;
  client::OrbitCamera& camera = *input.camera_;
  if (key == GLFW_KEY_LEFT) camera.orbit(-0.1f, 0.0f);
  else if (key == GLFW_KEY_RIGHT) camera.orbit(0.1f, 0.0f);
  else if (key == GLFW_KEY_UP) camera.orbit(0.0f, 0.1f);
  else if (key == GLFW_KEY_DOWN) camera.orbit(0.0f, -0.1f);
  else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD) camera.zoom(0.9f);
  else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT) camera.zoom(1.1f);
  else return;
  input.moveCamera();
}

void CameraInput::onFramebufferSize(GLFWwindow* window, int width, int height) {
  if (width < 1 || height < 1) return;
  inputOf(window).sendResize(width, height);
}

}  // namespace specula::view
