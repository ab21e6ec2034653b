#pragma once
// Adaptive tessellation of reflected geometry (Szabo 2013, ch. 4, shaders/tessellation): per
// visible mirror part and reflected object, rounds of split decisions and emission turn the object's
// triangles into finer ones where a straight virtual edge would miss the curved reflection, up to
// the level limit. A round runs five compute kernels: a cheap classification of every triangle lists
// the edges whose midpoint needs a search, the search runs only for those, a decision per triangle
// counts what it becomes, one invocation lays the part's runs out in the lists, and emission writes
// the finished triangles and the next round's children. Every count stays on the GPU: after round 0
// (a dispatch per object, over its mesh) each kernel runs once for all the part's objects, launched
// by an indirect dispatch that the previous round's layout wrote, and the virtual-objects pass draws
// by indirect commands, so the CPU issues every round of every level without waiting for any.
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class TessellationPass final : public Pass {
 public:
  static Result<std::unique_ptr<TessellationPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::Tessellation; }
  void execute(const FrameContext& frame) override;

 private:
  struct Programs {
    gl::ShaderProgram classify, dispatch, search, decide, layout, emit;
  };
  // One part's runs: [firstRun, firstRun + runCount) of the frame's.
  struct PartRuns {
    std::size_t planIndex = 0, firstRun = 0, runCount = 0;
  };
  explicit TessellationPass(Programs programs) : programs_(std::move(programs)) {}
  // Lists the frame's runs and hands them with their round-0 records to the buffers.
  std::vector<PartRuns> beginRuns(const FrameContext& frame) const;
  // Every round of one part, from its meshes down to the deepest level.
  void tessellatePart(const FrameContext& frame, const PartRuns& part) const;
  // What a kernel of a round runs over: working triangles, or the edges whose midpoint is searched.
  enum class Work { Triangles, Searches };
  // Runs `program` for a round of the part: in round 0 once per run that goes through rounds, over
  // its mesh; later once for the whole part, by the counts the last layout wrote.
  void dispatchRound(const FrameContext& frame, const gl::ShaderProgram& program, const PartRuns& part, int round,
                     Work work) const;

  Programs programs_;
};

}  // namespace specula::passes
