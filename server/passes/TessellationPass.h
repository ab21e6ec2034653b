#pragma once
// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4, shaders/tessellation): per
// visible mirror and reflected object, rounds of split decisions and transform-feedback emission
// (geometry shader) turn the object's triangles into finer ones where a straight virtual edge would
// miss the curved reflection, up to the level limit. A round decides in three compute steps: a cheap
// classification of every triangle lists the edges whose midpoint needs a search, the search runs
// only for those, and a decision per triangle reads the results.
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
  struct Programs {
    gl::ShaderProgram seed, classify, dispatch, search, decide, emit;
  };
  // One object's triangles in the round's working list.
  struct ObjectRun {
    const ReflectionSlotRange* range;
    std::size_t first = 0, triangles = 0;
  };
  TessellationPass(const gl::GlApi& gl, Programs programs) : programs_(std::move(programs)), emptyVertexArray_(gl) {}
  // Tessellates every object the mirror reflects; finished triangles are appended to the frame's list.
  void tessellateMirror(const FrameContext& frame, const MirrorSlots& mirror);
  // Decides which edges of every run's triangles split (classify, search, decide) and counts each
  // run's children and unsplit triangles into its pair of counters. `fromMesh`: round 0, whose
  // corners come from the objects' meshes and search slots.
  void decideRound(const FrameContext& frame, const std::vector<ObjectRun>& runs, bool fromMesh) const;
  // Writes the unsplit triangles (emitChildren false) or the children of the split ones among the
  // working triangles [firstTriangle, + triangles) of list `from` to `target` at `targetTriangle`;
  // `count` is how many that is.
  void emit(const FrameContext& frame, int from, std::size_t firstTriangle, std::size_t triangles, bool finishAll,
            bool emitChildren, GLuint target, std::size_t targetTriangle, std::size_t count) const;

  Programs programs_;
  gl::GlVertexArray emptyVertexArray_;  // emission reads its records from storage buffers
};

}  // namespace specula::passes
