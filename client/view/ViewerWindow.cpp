#include "ViewerWindow.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <vector>

#include "encode/PngEncoder.h"

namespace specula::view {

namespace {
constexpr GLenum kReadFramebuffer = 0x8CA8;   // GL_READ_FRAMEBUFFER
constexpr GLenum kColorAttachment0 = 0x8CE0;  // GL_COLOR_ATTACHMENT0
}  // namespace

Result<std::unique_ptr<ViewerWindow>> ViewerWindow::open(std::pair<int, int> size) {
  if (!glfwInit()) return Error{"cannot open a window: no display (set DISPLAY, or run under xvfb-run)"};
  GLFWwindow* glfwWindow = glfwCreateWindow(size.first, size.second, "Specula", nullptr, nullptr);
  if (!glfwWindow) {
    glfwTerminate();
    return Error{"cannot create an OpenGL window on this display"};
  }
  std::unique_ptr<ViewerWindow> window(new ViewerWindow(glfwWindow));
  glfwMakeContextCurrent(glfwWindow);
  glfwSwapInterval(1);
  auto genFramebuffers = reinterpret_cast<GenFramebuffers>(glfwGetProcAddress("glGenFramebuffers"));
  window->bindFramebuffer_ = reinterpret_cast<BindFramebuffer>(glfwGetProcAddress("glBindFramebuffer"));
  window->framebufferTexture2D_ = reinterpret_cast<FramebufferTexture2D>(glfwGetProcAddress("glFramebufferTexture2D"));
  window->blitFramebuffer_ = reinterpret_cast<BlitFramebuffer>(glfwGetProcAddress("glBlitFramebuffer"));
  if (!genFramebuffers || !window->bindFramebuffer_ || !window->framebufferTexture2D_ || !window->blitFramebuffer_)
    return Error{"this OpenGL lacks framebuffer blits (OpenGL 3.0 is needed)"};
  glGenTextures(1, &window->texture_);
  glBindTexture(GL_TEXTURE_2D, window->texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  genFramebuffers(1, &window->framebuffer_);
  return window;
}

ViewerWindow::~ViewerWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::pair<int, int> ViewerWindow::framebufferSize() const {
  std::pair<int, int> size;
  glfwGetFramebufferSize(window_, &size.first, &size.second);
  return size;
}

void ViewerWindow::show(const RgbaImage& image) {
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               image.pixels.data());
  textureWidth_ = image.width;
  textureHeight_ = image.height;
}

void ViewerWindow::present() {
  draw();
  glfwSwapBuffers(window_);
}

// Frame row 0 is the top, so the picture is blitted upside down.
std::pair<int, int> ViewerWindow::draw() {
  const auto [width, height] = framebufferSize();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (textureWidth_ == 0) return {width, height};
  bindFramebuffer_(kReadFramebuffer, framebuffer_);
  framebufferTexture2D_(kReadFramebuffer, kColorAttachment0, GL_TEXTURE_2D, texture_, 0);
  blitFramebuffer_(0, 0, textureWidth_, textureHeight_, 0, height, width, 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  bindFramebuffer_(kReadFramebuffer, 0);
  return {width, height};
}

Status ViewerWindow::saveScreenshot(const std::string& path) {
  const auto [width, height] = draw();  // into the back buffer: after a swap its contents are undefined
  std::vector<std::uint8_t> shot(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, shot.data());
  std::vector<std::uint8_t> topDown(shot.size());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(shot.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                topDown.data() + static_cast<std::size_t>(y) * row);
  auto png = encode::encodePng({topDown.data(), width, height});
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (png) file.write(reinterpret_cast<const char*>(png->data()), static_cast<std::streamsize>(png->size()));
  if (!png || !file) return Error{"could not write the screenshot '" + path + "'"};
  return {};
}

}  // namespace specula::view
