#include "render/SampleAccumulator.h"

#include <string>

#include "gl/GlErrors.h"

namespace specula::render {

Result<SampleAccumulator> SampleAccumulator::create(const gl::GlApi& gl) {
  auto accumulate =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "sample-accumulation/accumulate.frag"});
  if (!accumulate) return Error{accumulate.error()};
  auto resolve = gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "sample-accumulation/resolve.frag"});
  if (!resolve) return Error{resolve.error()};
  return SampleAccumulator(gl, std::move(accumulate.value()), std::move(resolve.value()));
}

namespace {

// What the passes may have left set that would clip, mask or test the full-screen draws and clears.
void resetDrawState(const gl::GlApi& gl) {
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_STENCIL_TEST);
  gl.Disable(GL_SCISSOR_TEST);
  gl.Disable(GL_CULL_FACE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace

Status SampleAccumulator::begin(const gl::RenderTarget& frame) {
  const gl::GlApi& gl = *gl_;
  if (!sum_ || sum_->width != frame.width() || sum_->height != frame.height()) {
    sum_.reset();  // free the old sum before allocating the new one
    Sum sum{frame.width(), frame.height(), gl::GlTexture(gl), gl::GlFramebuffer(gl)};
    gl.BindTexture(GL_TEXTURE_2D, sum.texture.id());
    gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, sum.width, sum.height);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, sum.framebuffer.id());
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, sum.texture.id(), 0);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      return Error{"the anti-aliasing sum's framebuffer is incomplete (" + gl::framebufferStatusName(status) +
                   "); out of GPU memory?"};
    sum_.emplace(std::move(sum));
  }
  gl.BindFramebuffer(GL_FRAMEBUFFER, sum_->framebuffer.id());
  resetDrawState(gl);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl.ClearBufferfv(GL_COLOR, 0, zero);
  return {};
}

void SampleAccumulator::drawFullScreen(const gl::ShaderProgram& program, GLuint texture, const char* sampler) const {
  const gl::GlApi& gl = *gl_;
  resetDrawState(gl);
  program.use();
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, texture);
  program.set(sampler, 0);
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.BindVertexArray(0);
  gl.BindTexture(GL_TEXTURE_2D, 0);
}

void SampleAccumulator::add(const gl::RenderTarget& frame, float weight) {
  const gl::GlApi& gl = *gl_;
  gl.BindFramebuffer(GL_FRAMEBUFFER, sum_->framebuffer.id());
  gl.Viewport(0, 0, sum_->width, sum_->height);
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // the sum is linear
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_ONE, GL_ONE);
  accumulate_.use();
  accumulate_.set("weight", weight);
  drawFullScreen(accumulate_, frame.colorTexture(), "frame");
  gl.Disable(GL_BLEND);
}

void SampleAccumulator::resolve(const gl::RenderTarget& frame) {
  const gl::GlApi& gl = *gl_;
  frame.bind();
  gl.Enable(GL_FRAMEBUFFER_SRGB);
  drawFullScreen(resolve_, sum_->texture.id(), "sum");
}

}  // namespace specula::render
