#pragma once
// Screen-space tessellation of parametric meshes on the GPU (after Hjelmervik & Hagen): every
// frame, every Bézier patch in view is cut by GL's tessellator into segments of about 8 pixels,
// finer where its projected outline bends (silhouettes), with shared edges cut alike so no crack
// opens (shaders/common/bezier-patch.tesc), and evaluated exactly (bezier-patch.tese). The scene
// pass and the mirror G-buffer draw parametric meshes this way; the probe measures what it makes.
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/GpuMeshes.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::passes {

// Sets what the patch stages read: the object's placement, the view and the target's size in pixels.
void setPatchView(const gl::ShaderProgram& program, const glm::mat4& objectToWorld, const glm::mat4& worldToClip,
                  glm::ivec2 viewportPixels);

// What the tessellation made of a scene's parametric meshes for one view.
struct PatchTessellationMeasure {
  std::size_t patches = 0;        // of the parametric meshes, in view or not
  std::size_t triangles = 0;      // generated, over every patch not dropped as out of view
  std::vector<float> pixelAreas;  // of the generated triangles at least partly on screen, in pixels
};

class PatchTessellationProbe {
 public:
  static Result<PatchTessellationProbe> create(const gl::GlApi& gl);

  // Tessellates every parametric mesh of `scene` at `pose` as the scene pass does for this view.
  PatchTessellationMeasure measure(const scene::Scene& scene, const scene::ScenePose& pose, const GpuMeshes& meshes,
                                   const glm::mat4& worldToClip, glm::ivec2 viewportPixels);

 private:
  PatchTessellationProbe(const gl::GlApi& gl, gl::ShaderProgram program)
      : gl_(&gl), program_(std::move(program)), areas_(gl) {}
  const gl::GlApi* gl_;
  gl::ShaderProgram program_;
  gl::GlBuffer areas_;
  std::size_t capacity_ = 0;  // areas the buffer holds
};

}  // namespace specula::passes
