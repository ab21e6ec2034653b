#pragma once
// GPU state the reflection passes share and keep between frames: the mirror G-buffer (one layer
// per mirror, with its pyramid), the reflected-vertex slots (last frame's texels live there) and
// the search statistics.
#include <algorithm>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/GpuMeshes.h"
#include "passes/GpuDeformation.h"
#include "passes/MeshBvh.h"
#include "passes/ReflectedVertex.h"
#include "passes/ReflectionSettings.h"
#include "passes/ReflectionSlots.h"
#include "passes/TessellationBuffers.h"
#include "scene/Scene.h"

namespace specula::passes {

// A rectangle of G-buffer texels (GL convention: origin bottom-left), half-open.
struct TexelRect {
  glm::ivec2 low{0}, high{0};
  bool empty() const { return high.x <= low.x || high.y <= low.y; }
  TexelRect united(const TexelRect& other) const;
};

class ReflectionResources {
 public:
  static constexpr int kCoarsestSide = 8;  // the cold start scans a pyramid level at most this big

  using MeshBvh = passes::MeshBvh;

  // `meshes` and `deformation` are the scene's, and outlive this.
  ReflectionResources(const gl::GlApi& gl, const scene::Scene& scene, const ReflectionSlots& slots,
                      const GpuMeshes& meshes, const GpuDeformation& deformation);

  // Sizes the G-buffer for a width × height frame with `margin` pixels added on each side, at
  // `texelsPerPixel` texels per pixel and `precision`; reallocates (and forgets every texel) only
  // when one of them changes.
  Status prepare(int frameWidth, int frameHeight, glm::ivec2 margin, float texelsPerPixel, GBufferPrecision precision);

  const ReflectionSlots& slots() const { return slots_; }
  glm::ivec2 size() const { return size_; }
  glm::ivec2 margin() const { return margin_; }  // frame pixels added on each side
  // The widened frame (frame + 2 × margin, in pixels) the G-buffer covers, at its resolution.
  glm::ivec2 coveredPixels() const { return coveredPixels_; }
  float texelsPerPixel() const {
    return static_cast<float>(size_.x) / static_cast<float>(std::max(coveredPixels_.x, 1));
  }
  GBufferPrecision precision() const { return precision_; }
  GLenum textureFormat() const { return precision_ == GBufferPrecision::Float16 ? GL_RGBA16F : GL_RGBA32F; }
  int coarseLevel() const { return coarseLevel_; }
  glm::ivec2 levelSize(int level) const { return glm::max(size_ >> level, glm::ivec2(1)); }
  GLuint positionTexture() const { return position_.id(); }
  GLuint normalTexture() const { return normal_.id(); }
  // (u, v, patch, 1) of each texel on a parametric mirror, one level, RGBA32F; 0 when no mirror of
  // the scene is parametric (the texture is not allocated).
  GLuint surfaceTexture() const { return surface_ ? surface_->id() : 0; }
  GLuint framebuffer() const { return framebuffer_.id(); }
  GLuint depthTexture() const { return depth_.id(); }
  GLuint reflectedVertices() const { return reflected_.id(); }
  GLuint statistics() const { return statistics_.id(); }
  // The part of each triangle of a mirror's search mesh (bytes, four to a uint), for mirrors of several parts.
  GLuint triangleParts(std::size_t mirrorObject) const { return triangleParts_.at(mirrorObject).id(); }
  // The hierarchy of a mesh (a mirror's own where it sees itself, an object's in a ray-cast part),
  // built on first use and kept; a deforming mesh's is refitted to the shape the mesh has now.
  const MeshBvh& meshBvh(std::uint32_t mesh);
  // The ray hierarchy (shaders/common/ray-hierarchy.glsl) at the G-buffer's size, one layer per
  // mirror part, levels down to one texel: allocated by the first call after the G-buffer is sized.
  void prepareRayHierarchy();
  GLuint rayHierarchySpheres() const { return rayHierarchySpheres_->id(); }
  GLuint rayHierarchyCones() const { return rayHierarchyCones_->id(); }
  int rayHierarchyTopLevel() const { return rayHierarchyTop_; }
  // The leaves a layer's hierarchy must rebuild this frame (its cones follow the eye): this frame's
  // cover and the one it was last built for, which then becomes this frame's.
  TexelRect takeRayHierarchyRebuild(int layer);
  // The explosion maps (shaders/common/explosion-map.glsl), `side` texels square: positions and
  // normals, two layers per mirror part (near, far), and the depth and framebuffer that draw them.
  // Reallocated when the side changes.
  void prepareExplosionMaps(int side);
  GLuint explosionPositions() const { return explosionPositions_->id(); }
  GLuint explosionNormals() const { return explosionNormals_->id(); }
  GLuint explosionDepth() const { return explosionDepth_->id(); }
  int explosionMapSide() const { return explosionSide_; }
  TessellationBuffers& tessellation() { return tessellation_; }
  const TessellationBuffers& tessellation() const { return tessellation_; }

  // The texels a mirror covers now (after the G-buffer pass), and those that changed this frame:
  // last frame's and this frame's cover together, which the pyramid must rebuild.
  TexelRect& coveredRect(int layer) { return covered_[static_cast<std::size_t>(layer)]; }
  // The same cover in frame pixels (GL origin, bottom left): low x, y, high x, y.
  glm::vec4 coveredFramePixels(int layer) const;
  TexelRect& changedRect(int layer) { return changed_[static_cast<std::size_t>(layer)]; }

  // Forgets every vertex's last texel, so the next search starts cold (camera jump, new scene).
  void resetCoherence();
  // Hands over the slot buffer (every vertex's last search result) and searches from `next`'s from
  // now on; an empty `next` is a fresh buffer that starts cold. Lets one renderer serve several views.
  gl::GlBuffer exchangeReflectedVertices(std::optional<gl::GlBuffer> next);
  void resetStatistics();
  std::vector<ReflectedVertex> readReflectedVertices() const;
  // One level of the last frame's ray hierarchy, every layer: spheres then cones, RGBA per texel
  // (a GPU readback; empty when no frame has built it).
  struct RayHierarchyLevel {
    glm::ivec2 size{0};
    std::vector<glm::vec4> spheres, cones;  // [layer][y][x]
  };
  RayHierarchyLevel readRayHierarchyLevel(int level) const;

 private:
  const gl::GlApi* gl_;
  const scene::Scene& scene_;
  const GpuMeshes& meshes_;
  const GpuDeformation& deformation_;
  const ReflectionSlots& slots_;
  glm::ivec2 size_{0}, margin_{0}, coveredPixels_{0};
  GBufferPrecision precision_ = GBufferPrecision::Float32;
  int coarseLevel_ = 0;
  gl::GlTexture position_, normal_, depth_;
  std::optional<gl::GlTexture> surface_;
  bool parametricMirror_ = false;  // some mirror's search mesh has patches: surface_ is needed
  std::optional<gl::GlTexture> rayHierarchySpheres_, rayHierarchyCones_;  // empty until a search uses them
  int rayHierarchyTop_ = 0;
  std::optional<gl::GlTexture> explosionPositions_, explosionNormals_, explosionDepth_;  // empty until a map is drawn
  int explosionSide_ = 0;
  std::vector<TexelRect> rayHierarchyCovered_;
  gl::GlFramebuffer framebuffer_;
  gl::GlBuffer reflected_, statistics_;
  std::map<std::size_t, gl::GlBuffer> triangleParts_;
  std::map<std::uint32_t, MeshBvh> meshBvhs_;
  std::vector<TexelRect> covered_, changed_;
  TessellationBuffers tessellation_;
};

// Sets the uniforms of shaders/common/gbuffer-texel.glsl: where a frame pixel lies in the G-buffer.
void setGBufferPixelMapping(const gl::ShaderProgram& program, const ReflectionResources& resources);

// The texture unit of the G-buffer's surface coordinates (units 2 to 5 hold the strategies' arrays).
inline constexpr GLuint kGBufferSurfaceUnit = 6;
// Binds the G-buffer's position and normal textures to texture units 0 and 1 and its surface
// coordinates to kGBufferSurfaceUnit, leaving unit 0 active.
void bindGBufferTextures(const gl::GlApi& gl, const ReflectionResources& resources);
// Points the program's (in use) gbufferPosition and gbufferNormal samplers at units 0 and 1; only the search's
// programs have gbufferSurface (setSearchUniforms).
void setGBufferSamplers(const gl::ShaderProgram& program);

}  // namespace specula::passes
