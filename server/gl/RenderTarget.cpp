#include "gl/RenderTarget.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "gl/GlErrors.h"

namespace specula::gl {

Result<RenderTarget> RenderTarget::create(const GlApi& gl, int width, int height) {
  GLint maxSize = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize)
    return Error{"frame size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1x1.." +
                 std::to_string(maxSize) + "x" + std::to_string(maxSize) + " (GL_MAX_TEXTURE_SIZE)"};
  RenderTarget target(gl, width, height);
  auto allocate = [&](const GlTexture& texture, GLenum format) {
    gl.BindTexture(GL_TEXTURE_2D, texture.id());
    gl.TexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  };
  allocate(target.color_, GL_SRGB8_ALPHA8);
  allocate(target.depthStencil_, GL_DEPTH24_STENCIL8);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.color_.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, target.depthStencil_.id(), 0);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    return Error{"off-screen framebuffer incomplete (" + framebufferStatusName(status) + "); out of GPU memory?"};
  return target;
}

void RenderTarget::bind() const {
  gl_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl_->Viewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> RenderTarget::readRgba() const {
  const std::size_t rowBytes = static_cast<std::size_t>(width_) * 4;
  std::vector<std::uint8_t> pixels(rowBytes * static_cast<std::size_t>(height_));
  gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL's row 0 is the bottom; every file and frame we write has row 0 at the top.
  std::vector<std::uint8_t> row(rowBytes);
  for (int top = 0, bottom = height_ - 1; top < bottom; ++top, --bottom) {
    std::uint8_t* a = pixels.data() + static_cast<std::size_t>(top) * rowBytes;
    std::uint8_t* b = pixels.data() + static_cast<std::size_t>(bottom) * rowBytes;
    std::memcpy(row.data(), a, rowBytes);
    std::memcpy(a, b, rowBytes);
    std::memcpy(b, row.data(), rowBytes);
  }
  return pixels;
}

}  // namespace specula::gl
