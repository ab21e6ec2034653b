#pragma once
// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4, shaders/tessellation): per
// visible mirror and reflected object, rounds of split decisions and emission turn the object's
// triangles into finer ones where a straight virtual edge would miss the curved reflection, up to
// the level limit. A round runs four compute kernels: a cheap classification of every triangle lists
// the edges whose midpoint needs a search, the search runs only for those, a decision per triangle
// reads the results, and emission writes the finished triangles and the next round's children.
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class TessellationPass final : public Pass {
 public:
  static Result<std::unique_ptr<TessellationPass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "tessellation"; }
  void execute(const FrameContext& frame) override;

 private:
  struct Programs {
    gl::ShaderProgram classify, dispatch, search, decide, emit;
  };
  // One object's triangles in the round's working list.
  struct ObjectRun {
    const ReflectionSlotRange* range;
    std::size_t first = 0, triangles = 0;
  };
  explicit TessellationPass(Programs programs) : programs_(std::move(programs)) {}
  // Tessellates every object the mirror reflects; finished triangles are appended to the frame's
  // list, which this part may fill up to `finishedBudget` triangles in all.
  void tessellateMirror(const FrameContext& frame, const PlannedMirror& mirror, std::size_t finishedBudget);
  // Decides which edges of every run's triangles split (classify, search, decide) and counts each
  // run's children and unsplit triangles into its pair of counters. `fromMesh`: round 0, whose
  // corners come from the objects' meshes and search slots.
  void decideRound(const FrameContext& frame, const std::vector<ObjectRun>& runs, bool fromMesh) const;
  // Sets the uniforms of run `i` (and in round 0 binds its mesh) for a kernel of the round.
  void setRun(const FrameContext& frame, const gl::ShaderProgram& program, const std::vector<ObjectRun>& runs, std::size_t i,
              bool fromMesh) const;

  Programs programs_;
};

}  // namespace specula::passes
