#pragma once
// Builds the ray hierarchy of each searched mirror part for this frame's eye (shaders/ray-hierarchy):
// bounding spheres of its positions and cones of its reflected rays, for the hierarchy search.
#include <memory>

#include "base/Result.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class RayHierarchyPass final : public Pass {
 public:
  static Result<std::unique_ptr<RayHierarchyPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::RayHierarchy; }
  void execute(const FrameContext& frame) override;

 private:
  RayHierarchyPass(gl::ShaderProgram leaves, gl::ShaderProgram level)
      : leaves_(std::move(leaves)), level_(std::move(level)) {}
  gl::ShaderProgram leaves_, level_;
};

}  // namespace specula::passes
