#pragma once
// Renders each visible mirror's (closed) surface into its G-buffer layer: world positions and
// normals through the eye's frustum widened by the margin (Estalella et al. 2006, §4 and §5.2).
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class MirrorGBufferPass final : public Pass {
 public:
  static Result<std::unique_ptr<MirrorGBufferPass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "mirror-gbuffer"; }
  std::span<const std::string_view> reads() const override { return {}; }
  std::span<const std::string_view> writes() const override;
  void execute(const FrameContext& frame) override;

 private:
  explicit MirrorGBufferPass(gl::ShaderProgram program) : program_(std::move(program)) {}
  gl::ShaderProgram program_;
};

}  // namespace specula::passes
