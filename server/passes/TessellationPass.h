#pragma once
// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4, shaders/tessellation): per
// visible mirror and reflected object, rounds of split decisions (compute) and transform-feedback
// emission (geometry shader) turn the object's triangles into finer ones where a straight virtual
// edge would miss the curved reflection, up to the level limit.
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class TessellationPass final : public Pass {
 public:
  static Result<std::unique_ptr<TessellationPass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "tessellation"; }
  std::span<const std::string_view> reads() const override;
  std::span<const std::string_view> writes() const override;
  void execute(const FrameContext& frame) override;

 private:
  TessellationPass(const gl::GlApi& gl, gl::ShaderProgram seed, gl::ShaderProgram split, gl::ShaderProgram emit)
      : seed_(std::move(seed)), split_(std::move(split)), emit_(std::move(emit)), emptyVertexArray_(gl) {}
  // Tessellates every object the mirror reflects; finished triangles are appended to the frame's list.
  void tessellateMirror(const FrameContext& frame, const MirrorSlots& mirror);
  // Runs the split decisions for working triangles [firstTriangle, + triangles), counting into
  // the object's pair of counters.
  void dispatchSplit(const FrameContext& frame, std::size_t firstTriangle, std::size_t triangles, std::size_t counterIndex) const;
  // Writes the unsplit triangles (emitChildren false) or the children of the split ones among the
  // working triangles [firstTriangle, + triangles) of list `from` to `target` at `targetTriangle`;
  // `count` is how many that is.
  void emit(const FrameContext& frame, int from, std::size_t firstTriangle, std::size_t triangles, bool finishAll,
            bool emitChildren, GLuint target, std::size_t targetTriangle, std::size_t count) const;

  gl::ShaderProgram seed_, split_, emit_;
  gl::GlVertexArray emptyVertexArray_;  // emission reads its records from storage buffers
};

}  // namespace specula::passes
