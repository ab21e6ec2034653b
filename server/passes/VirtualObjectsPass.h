#pragma once
// Rasterizes each visible mirror's virtual objects into the mirror's stencil area of a reflection
// buffer, depth-tested among themselves (nearest surface wins), lit at the real objects' positions;
// then adds each mirror's reflection, weighted by its reflectivity, over its surface colour.
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
  void execute(const FrameContext& frame) override;

 private:
  VirtualObjectsPass(const gl::GlApi& gl, gl::ShaderProgram objects, gl::ShaderProgram tessellated, gl::ShaderProgram region,
                     gl::ShaderProgram rayCast, gl::ShaderProgram composite)
      : objects_(std::move(objects)),
        tessellated_(std::move(tessellated)),
        region_(std::move(region)),
        rayCast_(std::move(rayCast)),
        composite_(std::move(composite)),
        emptyVertexArray_(gl),
        framebuffer_(gl),
        reflection_(gl) {}
  // Sizes the reflection buffer like the frame (kept while the size stays) and binds it with the
  // frame's depth and stencil.
  void bindReflectionBuffer(const FrameContext& frame);
  // Sets the depth inside the mirror's stencil to the far plane.
  void resetMirrorDepth(const FrameContext& frame) const;
  // Casts the part's reflected rays against one object's mesh (the mirror's own where it sees itself)
  // and draws the nearest hits at their depth.
  void rayCast(const FrameContext& frame, const MirrorSlots& mirror, std::size_t object) const;
  // Draws the mirror's virtual objects with whichever program each needs.
  void drawObjects(const FrameContext& frame, const PlannedMirror& mirror) const;
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
  gl::ShaderProgram rayCast_;
  gl::ShaderProgram composite_;
  gl::GlVertexArray emptyVertexArray_;  // the full-screen triangle needs no attributes
  gl::GlFramebuffer framebuffer_;       // the reflection buffer with the frame's depth and stencil
  gl::GlTexture reflection_;            // RGBA16F, linear; alpha marks pixels something landed on
  glm::ivec2 reflectionSize_{0};
};

}  // namespace specula::passes
