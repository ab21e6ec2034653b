#pragma once
// The environment-map baseline: per visible mirror, a cube map of its reflected objects rendered
// from the mirror's centre, then looked up per mirror pixel with the eye ray reflected about the
// G-buffer normal. What most engines draw instead of virtual objects: right for distant
// surroundings, wrong by the parallax of everything near the mirror.
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class EnvironmentMapPass final : public Pass {
 public:
  static Result<std::unique_ptr<EnvironmentMapPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::EnvironmentMap; }
  void execute(const FrameContext& frame) override;

 private:
  EnvironmentMapPass(const gl::GlApi& gl, gl::ShaderProgram capture, gl::ShaderProgram lookup)
      : capture_(std::move(capture)),
        lookup_(std::move(lookup)),
        cube_(gl),
        depth_(gl),
        framebuffer_(gl),
        emptyVertexArray_(gl) {}
  // (Re)allocates the cube map and its depth when the face size changes.
  void prepare(const gl::GlApi& gl, int faceSize);
  // Renders the six faces seen from `centre`: the mirror's reflected objects on the background.
  void capture(const FrameContext& frame, std::size_t mirrorObject, const glm::vec3& centre) const;

  gl::ShaderProgram capture_;  // the scene shaders, from the cube's centre
  gl::ShaderProgram lookup_;   // full-screen, under the mirror's stencil
  gl::GlTexture cube_, depth_;
  gl::GlFramebuffer framebuffer_;
  gl::GlVertexArray emptyVertexArray_;
  int faceSize_ = 0;
};

}  // namespace specula::passes
