#pragma once
// Finds every reflected vertex's reflection point in each visible mirror (shaders/search).
#include <memory>
#include <optional>
#include <string>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

// The uniforms of shaders/search/ (reflection-search.glsl and the strategies it includes): per frame, then per mirror.
void setSearchUniforms(const gl::ShaderProgram& program, const FrameContext& frame);
void setSearchMirror(const gl::ShaderProgram& program, const FrameContext& frame, const MirrorSlots& mirror);

// What in `scene` this GL cannot search, naming the limit and the fix: the slot buffer and each
// reflected mesh's vertex buffer are bound whole as shader storage, and one dispatch covers a mesh.
std::optional<std::string> searchLimitProblem(const gl::GlApi& gl, const scene::Scene& scene,
                                              const ReflectionSlots& slots);

class SearchPass final : public Pass {
 public:
  static Result<std::unique_ptr<SearchPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::Search; }
  void execute(const FrameContext& frame) override;

 private:
  explicit SearchPass(gl::ShaderProgram program) : program_(std::move(program)) {}
  gl::ShaderProgram program_;
};

}  // namespace specula::passes
