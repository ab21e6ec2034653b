#pragma once
// Rasterizes each visible mirror's virtual objects into the mirror's stencil area, depth-tested
// among themselves (nearest virtual surface wins), lit at the real objects' positions and added
// with the mirror's reflectivity over its surface colour.
#include <memory>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class VirtualObjectsPass final : public Pass {
 public:
  static Result<std::unique_ptr<VirtualObjectsPass>> create(const gl::GlApi& gl);

  std::string_view name() const override { return "virtual-objects"; }
  std::span<const std::string_view> reads() const override;
  std::span<const std::string_view> writes() const override;
  void execute(const FrameContext& frame) override;

 private:
  VirtualObjectsPass(const gl::GlApi& gl, gl::ShaderProgram objects, gl::ShaderProgram tessellated, gl::ShaderProgram region,
                     gl::ShaderProgram selfReflection)
      : objects_(std::move(objects)),
        tessellated_(std::move(tessellated)),
        region_(std::move(region)),
        selfReflection_(std::move(selfReflection)),
        emptyVertexArray_(gl) {}
  // Sets the depth inside the mirror's stencil to the far plane.
  void resetMirrorDepth(const FrameContext& frame) const;
  // Where the part's reflected rays meet the mirror itself: the mirror's colour at that depth.
  void drawSelfReflection(const FrameContext& frame, const MirrorSlots& mirror, bool depthOnly) const;
  // Draws the mirror's virtual objects with whichever program each needs.
  void drawObjects(const FrameContext& frame, const MirrorSlots& mirror) const;
  // One reflected object from its own mesh and search slots (objects_ in use).
  void drawMesh(const FrameContext& frame, const ReflectionSlotRange& range) const;
  template <typename Value>
  void setForBoth(const char* name, const Value& value) const {
    for (const gl::ShaderProgram* program : {&objects_, &tessellated_}) {
      program->use();
      program->set(name, value);
    }
  }

  gl::ShaderProgram objects_;      // scene meshes at their search slots
  gl::ShaderProgram tessellated_;  // the tessellation pass's finished triangles
  gl::ShaderProgram region_;
  gl::ShaderProgram selfReflection_;
  gl::GlVertexArray emptyVertexArray_;  // the full-screen triangle needs no attributes
};

}  // namespace specula::passes
