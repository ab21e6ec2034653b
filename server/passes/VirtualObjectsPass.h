#pragma once
// Rasterizes each visible mirror's virtual objects into the mirror's stencil area of a reflection
// buffer, depth-tested among themselves (nearest surface wins), lit at the real objects' positions;
// then adds each mirror's reflection, weighted by its reflectivity, over its surface colour.
#include <cstdint>
#include <memory>
#include <vector>

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
  // Per part of the last frame's plan, the pixels its virtual objects left uncovered that were
  // ray-cast (settings.rayCastUncovered; 0 for ray-cast parts). A GPU readback.
  std::vector<std::uint32_t> readUncoveredCounts() const;

 private:
  VirtualObjectsPass(const gl::GlApi& gl, gl::ShaderProgram objects, gl::ShaderProgram tessellated, gl::ShaderProgram region,
                     gl::ShaderProgram rayCast, gl::ShaderProgram findUncovered, gl::ShaderProgram uncoveredPixel,
                     gl::ShaderProgram composite)
      : gl_(&gl),
        objects_(std::move(objects)),
        tessellated_(std::move(tessellated)),
        region_(std::move(region)),
        rayCast_(std::move(rayCast)),
        findUncovered_(std::move(findUncovered)),
        uncoveredPixel_(std::move(uncoveredPixel)),
        composite_(std::move(composite)),
        emptyVertexArray_(gl),
        framebuffer_(gl),
        reflection_(gl),
        stencilOnly_(gl),
        uncovered_(gl),
        reflectedBoxes_(gl),
        uncoveredCounts_(gl) {}
  struct PixelRect {
    glm::ivec2 low, high;  // frame pixels, high exclusive
    glm::ivec2 size() const { return high - low; }
  };
  // A rectangle of frame pixels (GL origin: low x, y, high x, y) as whole pixels inside the frame.
  static PixelRect framePixels(const glm::vec4& rect, const FrameContext& frame);
  // Sizes the reflection buffer like the frame (kept while the size stays) and binds it with the
  // frame's depth and stencil.
  void bindReflectionBuffer(const FrameContext& frame);
  // Sets the depth inside the mirror's stencil to the far plane.
  void resetMirrorDepth(const FrameContext& frame) const;
  // Casts the part's reflected rays against one object's mesh (the mirror's own where it sees itself)
  // and draws the nearest hits at their depth.
  void rayCast(const FrameContext& frame, const MirrorSlots& mirror, std::size_t object) const;
  // Ray-casts against the part's reflected objects the pixels its virtual objects left uncovered, or
  // on an environment-map part those its cube map cannot serve within the error budget; their
  // number goes to uncoveredCounts_[partIndex].
  void rayCastUncovered(const FrameContext& frame, const PlannedMirror& planned, std::size_t partIndex);
  // Uses `program`, which reads the reflection buffer and the G-buffer at each pixel and may test the
  // environment-map bound there (the uncovered-pixel list, the composite).
  void useReadingReflection(const gl::ShaderProgram& program, const FrameContext& frame) const;
  // Uses `program` (ray-cast.frag) with the uniforms and buffers of one object seen in the part.
  void prepareRayCast(const FrameContext& frame, const gl::ShaderProgram& program, const MirrorSlots& mirror,
                      std::size_t object) const;
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

  const gl::GlApi* gl_;
  gl::ShaderProgram objects_;      // scene meshes at their search slots
  gl::ShaderProgram tessellated_;  // the tessellation pass's finished triangles
  gl::ShaderProgram region_;
  gl::ShaderProgram rayCast_;         // over a full-screen triangle
  gl::ShaderProgram findUncovered_;   // lists a part's uncovered pixels
  gl::ShaderProgram uncoveredPixel_;  // ray-cast.frag at the listed pixels, drawn as points
  gl::ShaderProgram composite_;
  gl::GlVertexArray emptyVertexArray_;  // the full-screen triangle needs no attributes
  gl::GlFramebuffer framebuffer_;       // the reflection buffer with the frame's depth and stencil
  gl::GlTexture reflection_;            // RGBA16F, linear; alpha marks pixels something landed on
  glm::ivec2 reflectionSize_{0};
  struct DrawCommand {  // DrawArraysIndirectCommand
    std::uint32_t count, instances, first, baseInstance;
  };
  gl::GlFramebuffer stencilOnly_;  // the frame's depth and stencil alone: the uncovered pixels are listed through it
  gl::GlBuffer uncovered_;  // a DrawCommand and the uncovered pixels of one part (uncovered-pixels.glsl)
  GLsizeiptr uncoveredBytes_ = 0;
  gl::GlBuffer reflectedBoxes_;  // world bounds of the part's reflected objects (uncovered-pixels.frag)
  gl::GlBuffer uncoveredCounts_;  // one uint per planned part
  std::size_t plannedParts_ = 0;
};

}  // namespace specula::passes
