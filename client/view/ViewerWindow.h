#pragma once
// The GLFW window and its OpenGL context: shows the latest frame stretched over the window and can save what it
// showed.
#include <GLFW/glfw3.h>

#include <memory>
#include <string>
#include <utility>

#include "JpegDecoder.h"
#include "base/Result.h"

namespace specula::view {

class ViewerWindow {
 public:
  // A window of `size` with a current OpenGL context, or why not (no display, no framebuffer blits).
  static Result<std::unique_ptr<ViewerWindow>> open(std::pair<int, int> size);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  // In pixels: a HiDPI window has more than the size asked for.
  std::pair<int, int> framebufferSize() const;
  bool shouldClose() const { return glfwWindowShouldClose(window_) != 0; }
  void pollEvents() const { glfwPollEvents(); }
  void setTitle(const std::string& title) const { glfwSetWindowTitle(window_, title.c_str()); }

  // The picture to draw from now on.
  void show(const RgbaImage& image);
  // Draws the picture and swaps buffers.
  void present();
  // Draws the picture once more, reads the window back and writes it to `path` as PNG.
  Status saveScreenshot(const std::string& path);

 private:
  using GenFramebuffers = void (*)(GLsizei, GLuint*);
  using BindFramebuffer = void (*)(GLenum, GLuint);
  using FramebufferTexture2D = void (*)(GLenum, GLenum, GLenum, GLuint, GLint);
  using BlitFramebuffer = void (*)(GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum);

  explicit ViewerWindow(GLFWwindow* window) : window_(window) {}
  // Draws into the back buffer; returns the framebuffer size it drew at.
  std::pair<int, int> draw();

  GLFWwindow* window_;
  // OpenGL 3.0 entry points that GLFW's header does not declare.
  BindFramebuffer bindFramebuffer_ = nullptr;
  FramebufferTexture2D framebufferTexture2D_ = nullptr;
  BlitFramebuffer blitFramebuffer_ = nullptr;
  GLuint texture_ = 0, framebuffer_ = 0;
  int textureWidth_ = 0, textureHeight_ = 0;  // 0 until the first picture
};

}  // namespace specula::view
