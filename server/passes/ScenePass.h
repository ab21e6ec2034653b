#pragma once
// Draws every object as seen directly from the eye, lit, into colour and depth.
// Mirrors are drawn with their own (base) colour; reflections are added by later passes.
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class ScenePass final : public Pass {
 public:
  static Result<std::unique_ptr<ScenePass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "scene"; }
  std::span<const std::string_view> reads() const override { return {}; }
  std::span<const std::string_view> writes() const override;
  void execute(const FrameContext& frame) override;

 private:
  explicit ScenePass(gl::ShaderProgram program) : program_(std::move(program)) {}
  gl::ShaderProgram program_;
};

}  // namespace specula::passes
