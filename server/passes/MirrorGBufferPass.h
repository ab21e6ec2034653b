#pragma once
// Renders each visible mirror part's (closed) surface into its G-buffer layer: world positions and
// normals through the eye's frustum widened by the margin (Estalella et al. 2006, §4 and §5.2).
// Other parts of the same mirror write depth but no texel, so they still hide what lies behind them.
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class MirrorGBufferPass final : public Pass {
 public:
  static Result<std::unique_ptr<MirrorGBufferPass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "mirror-gbuffer"; }
  void execute(const FrameContext& frame) override;

 private:
  MirrorGBufferPass(const gl::GlApi& gl, gl::ShaderProgram mesh, gl::ShaderProgram patch, gl::ShaderProgram quadric)
      : mesh_(std::move(mesh)), patch_(std::move(patch)), quadric_(std::move(quadric)), emptyVertexArray_(gl) {}
  gl::ShaderProgram mesh_;     // the mirror's (search) mesh
  gl::ShaderProgram patch_;    // a parametric mesh tessellated for the view, each texel on its exact patch
  gl::ShaderProgram quadric_;  // an exact quadric inside its proxy box
  gl::GlVertexArray emptyVertexArray_;
};

}  // namespace specula::passes
