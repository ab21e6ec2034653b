#pragma once
// Anti-aliasing by supersampling: the renderer draws the frame once per sample point with the
// projection shifted by that point's offset (math::samplePattern), and this averages the frames in
// linear light (an RGBA32F sum, kept while frames keep their size) and writes the average back
// into the frame, sRGB-encoded. The reference ray tracer averages the same sample points.
#include <optional>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderProgram.h"

namespace specula::render {

class SampleAccumulator {
 public:
  static Result<SampleAccumulator> create(const gl::GlApi& gl);

  // Clears the sum to `frame`'s size (allocating it only when the size changed).
  Status begin(const gl::RenderTarget& frame);
  // Adds `frame`'s colour times `weight`.
  void add(const gl::RenderTarget& frame, float weight);
  // Writes the sum into `frame`'s colour; depth and stencil are left as the last sample's.
  void resolve(const gl::RenderTarget& frame);

 private:
  SampleAccumulator(const gl::GlApi& gl, gl::ShaderProgram accumulate, gl::ShaderProgram resolve)
      : gl_(&gl), accumulate_(std::move(accumulate)), resolve_(std::move(resolve)), emptyVertexArray_(gl) {}
  void drawFullScreen(const gl::ShaderProgram& program, GLuint texture, const char* sampler) const;

  const gl::GlApi* gl_;
  gl::ShaderProgram accumulate_, resolve_;
  gl::GlVertexArray emptyVertexArray_;
  struct Sum {
    int width, height;
    gl::GlTexture texture;
    gl::GlFramebuffer framebuffer;
  };
  std::optional<Sum> sum_;
};

}  // namespace specula::render
