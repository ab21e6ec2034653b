#pragma once
// An off-screen frame: sRGB colour (shading is linear, stored bytes are sRGB) plus depth–stencil,
// both textures so later passes can sample them.
#include <cstdint>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlObject.h"

namespace specula::gl {

class RenderTarget {
 public:
  // Fails with a message when the size is outside [1, GL_MAX_TEXTURE_SIZE] or the FBO is incomplete.
  static Result<RenderTarget> create(const GlApi& gl, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint colorTexture() const { return color_.id(); }
  GLuint depthStencilTexture() const { return depthStencil_.id(); }

  // Binds the framebuffer and sets the viewport to cover it (a surfaceless context starts at 0×0).
  void bind() const;
  // Tightly packed RGBA8 sRGB pixels, row 0 at the top.
  std::vector<std::uint8_t> readRgba() const;

 private:
  RenderTarget(const GlApi& gl, int width, int height)
      : gl_(&gl), width_(width), height_(height), framebuffer_(gl), color_(gl), depthStencil_(gl) {}
  const GlApi* gl_;
  int width_, height_;
  GlFramebuffer framebuffer_;
  GlTexture color_;
  GlTexture depthStencil_;
};

}  // namespace specula::gl
