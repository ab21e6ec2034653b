#pragma once
// Rasterizes each visible mirror's virtual objects into the mirror's stencil area of a reflection
// buffer, depth-tested among themselves (nearest surface wins), lit at the real objects' positions;
// then adds each mirror's reflection, weighted by its reflectivity, over its surface colour.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/GpuReadback.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class VirtualObjectsPass final : public Pass {
 public:
  static Result<std::unique_ptr<VirtualObjectsPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::VirtualObjects; }
  void execute(const FrameContext& frame) override;
  // What the last frame's plan did per part, queued on `readback` after the frame's passes and read
  // from it once it has waited.
  struct PartStatistics {
    std::uint32_t uncoveredRayCast = 0;  // pixels no virtual object covered, ray-cast (settings.rayCastUncovered)
    CastTileCount castTiles;             // a ray-cast part's tiles (zero for parts not ray-cast)
  };
  void queueStatistics(gl::GpuReadback& readback);
  std::vector<PartStatistics> readStatistics(const gl::GpuReadback& readback) const;

 private:
  VirtualObjectsPass(const gl::GlApi& gl, gl::ShaderProgram objects, gl::ShaderProgram tessellated,
                     gl::ShaderProgram region, gl::ShaderProgram rayCast, gl::ShaderProgram rayCastTiles,
                     gl::ShaderProgram classifyTiles, gl::ShaderProgram findUncovered, gl::ShaderProgram uncoveredPixel,
                     gl::ShaderProgram reflectedEnvironment, gl::ShaderProgram composite)
      : gl_(&gl),
        objects_(std::move(objects)),
        tessellated_(std::move(tessellated)),
        region_(std::move(region)),
        rayCast_(std::move(rayCast)),
        rayCastTiles_(std::move(rayCastTiles)),
        classifyTiles_(std::move(classifyTiles)),
        findUncovered_(std::move(findUncovered)),
        uncoveredPixel_(std::move(uncoveredPixel)),
        reflectedEnvironment_(std::move(reflectedEnvironment)),
        composite_(std::move(composite)),
        emptyVertexArray_(gl),
        framebuffer_(gl),
        reflection_(gl),

        stencilOnly_(gl),
        uncovered_(gl),
        reflectedBoxes_(gl),
        uncoveredCounts_(gl),
        castObjects_(gl),
        castDraws_(gl),
        castTileLists_(gl),
        nearestHits_(gl) {}
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
  // Writes what the part reflects from the environment over its pixels (alpha 0, depth untouched).
  void drawReflectedEnvironment(const FrameContext& frame, const MirrorSlots& mirror, float reflectivity) const;
  // Casts the part's reflected rays against one object's mesh (the mirror's own where it sees itself)
  // and draws the nearest hits at their depth.
  void rayCast(const FrameContext& frame, const MirrorSlots& mirror, std::size_t object) const;
  // For every ray-cast part, lists per object the 8×8 tiles whose rays may reach it (castParts_).
  void classifyCastTiles(const FrameContext& frame);
  // Casts a ray-cast part's objects, nearest to the mirror first, each on its listed tiles only.
  void rayCastPart(const FrameContext& frame, std::size_t partIndex) const;
  // Uses `program` with the uniforms of the part's reflected rays (virtual-objects/cast-ray.glsl).
  static void setCastRay(const FrameContext& frame, const gl::ShaderProgram& program, const MirrorSlots& mirror);
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
  // One reflected object from its own mesh and search slots (objects_ in use); by the
  // DrawElementsIndirectCommand at `indirect` of the bound indirect buffer when given.
  void drawMesh(const FrameContext& frame, const ReflectionSlotRange& range,
                std::optional<GLintptr> indirect = std::nullopt) const;
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
  gl::ShaderProgram rayCast_;               // over a full-screen triangle
  gl::ShaderProgram rayCastTiles_;          // over the tiles an object's list names
  gl::ShaderProgram classifyTiles_;         // lists each object's tiles
  gl::ShaderProgram findUncovered_;         // lists a part's uncovered pixels
  gl::ShaderProgram uncoveredPixel_;        // ray-cast.frag at the listed pixels, drawn as points
  gl::ShaderProgram reflectedEnvironment_;  // what a part reflects where nothing lands, under its virtual objects
  gl::ShaderProgram composite_;
  gl::GlVertexArray emptyVertexArray_;  // the full-screen triangle needs no attributes
  gl::GlFramebuffer framebuffer_;       // the reflection buffer with the frame's depth and stencil
  gl::GlTexture reflection_;            // RGBA16F, linear; alpha marks pixels something landed on
  glm::ivec2 reflectionSize_{0};
  struct DrawCommand {  // DrawArraysIndirectCommand
    std::uint32_t count, instances, first, baseInstance;
  };
  gl::GlFramebuffer stencilOnly_;  // the frame's depth and stencil alone: the uncovered pixels are listed through it
  gl::GlBuffer uncovered_;         // a DrawCommand and the uncovered pixels of one part (uncovered-pixels.glsl)
  GLsizeiptr uncoveredBytes_ = 0;
  gl::GlBuffer reflectedBoxes_;   // world bounds of the part's reflected objects (uncovered-pixels.frag)
  gl::GlBuffer uncoveredCounts_;  // one uint per planned part
  std::size_t plannedParts_ = 0;
  std::size_t uncoveredHandle_ = 0, castHandle_ = 0, castCommands_ = 0;  // queueStatistics()'s copies
  struct CastPart {                                                      // one planned part's ray cast this frame
    std::vector<std::size_t> objects;                                    // in draw order: nearest to the mirror first
    bool tiled = false;  // false: each object over all the part's pixels
    glm::ivec2 firstTile{0}, tileExtent{0};
    std::size_t tileCapacity = 0;          // tiles of the part's pixels: each object's list has room for all
    std::size_t firstObject = 0;           // its objects' first sphere and DrawCommand
    std::size_t firstEntry = 0;            // its objects' first list entry
    glm::ivec2 pixelLow{0}, pixelHigh{0};  // its pixels, whose nearest hits it keeps
    std::size_t firstHit = 0;              // their first entry in nearestHits_, row by row
  };
  // Sets the uniforms by which `program` finds the part's nearest hits (cast-ray.glsl).
  static void setNearestHits(const gl::ShaderProgram& program, const CastPart& part);
  std::vector<CastPart> castParts_;    // per planned part
  gl::GlBuffer castObjects_;           // world bounding spheres of every tiled part's objects
  gl::GlBuffer castDraws_;             // a DrawCommand per object: two triangles per listed tile
  gl::GlGrowingBuffer castTileLists_;  // per object, room for every tile of its part
  // Per pixel of each tiled part, the nearest hit distance cast so far (float bits), which bounds
  // the traversal of the objects cast after it.
  gl::GlGrowingBuffer nearestHits_;
};

}  // namespace specula::passes
