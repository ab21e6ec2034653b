#pragma once
// Draws every object as seen directly from the eye, lit, into colour and depth.
// Mirrors are drawn with their own (base) colour; reflections are added by later passes. A mirror
// with an exact quadric is ray-cast per fragment, so its outline is the quadric's, not its mesh's;
// a parametric mesh is tessellated for the view (passes/PatchTessellation.h).
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class ScenePass final : public Pass {
 public:
  static Result<std::unique_ptr<ScenePass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::Scene; }
  void execute(const FrameContext& frame) override;

 private:
  ScenePass(const gl::GlApi& gl, gl::ShaderProgram program, gl::ShaderProgram quadric, gl::ShaderProgram patches,
            gl::ShaderProgram environment)
      : program_(std::move(program)),
        quadric_(std::move(quadric)),
        patches_(std::move(patches)),
        environment_(std::move(environment)),
        emptyVertexArray_(gl) {}
  gl::ShaderProgram program_;
  gl::ShaderProgram quadric_;      // exact quadrics inside their proxy boxes
  gl::ShaderProgram patches_;      // parametric meshes, tessellated for the view
  gl::ShaderProgram environment_;  // the sky or image behind everything
  gl::GlVertexArray emptyVertexArray_;
};

}  // namespace specula::passes
