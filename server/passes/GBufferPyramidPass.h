#pragma once
// Builds the G-buffer pyramid of each visible mirror (only the region that changed), which lets a
// cold-started search go coarse to fine instead of walking hundreds of texels.
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class GBufferPyramidPass final : public Pass {
 public:
  static Result<std::unique_ptr<GBufferPyramidPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::GBufferPyramid; }
  void execute(const FrameContext& frame) override;

 private:
  GBufferPyramidPass(gl::ShaderProgram full, gl::ShaderProgram half) : full_(std::move(full)), half_(std::move(half)) {}
  gl::ShaderProgram full_, half_;  // for RGBA32F and RGBA16F G-buffers: image formats must match
};

}  // namespace specula::passes
