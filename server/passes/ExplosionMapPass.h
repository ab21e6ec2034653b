#pragma once
// Ofek & Rappoport's (1998) explosion maps for each part searched with SearchStrategy::ExplosionMap
// (shaders/explosion-map): per part and frame, a near map (the reflected eye rays through a sphere
// bounding the part) and a far one (a sphere bounding the scene), each texel the mirror position and
// normal whose reflected ray leaves in that direction from the part's centre.
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

// The map's frame for one part: centre C and radii of the near and far spheres, axes with z from C
// to the eye. Set on every program that builds or reads the maps (common/explosion-map.glsl).
void setExplosionMapFrame(const gl::ShaderProgram& program, const FrameContext& frame, const MirrorSlots& mirror);

class ExplosionMapPass final : public Pass {
 public:
  static Result<std::unique_ptr<ExplosionMapPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::ExplosionMap; }
  void execute(const FrameContext& frame) override;

 private:
  ExplosionMapPass(const gl::GlApi& gl, gl::ShaderProgram program) : program_(std::move(program)), framebuffer_(gl) {}
  gl::ShaderProgram program_;
  gl::GlFramebuffer framebuffer_;
};

}  // namespace specula::passes
