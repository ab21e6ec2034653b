#pragma once
// Renders each visible mirror part's (closed) surface into its G-buffer layer: world positions and
// normals through the eye's frustum widened by the margin (Estalella et al. 2006, §4 and §5.2).
// A mirror of several parts is drawn whole for each part, so that the other parts still hide what
// lies behind it, with only the part's own texels marked. A parametric one is drawn (tessellated and
// evaluated per texel) once, into scratch textures that record each texel's part, and each part's
// layer is copied from them: on llvmpipe that halves its G-buffer pass, where a mesh's redraw costs
// less than the copies (the generated engine's 22 parts).
#include <memory>
#include <optional>

#include "base/Result.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "passes/Pass.h"

namespace specula::passes {

class MirrorGBufferPass final : public Pass {
 public:
  static Result<std::unique_ptr<MirrorGBufferPass>> create(const gl::GlApi& gl);

  PassId id() const override { return PassId::MirrorGBuffer; }
  void execute(const FrameContext& frame) override;

 private:
  // The textures a mirror of several parts is drawn into before its parts' layers are copied out.
  struct Scratch {
    explicit Scratch(const gl::GlApi& gl) : position(gl), normal(gl), surface(gl) {}
    gl::GlTexture position, normal, surface;
    glm::ivec2 size{0};
    GLenum format = 0;
  };

  MirrorGBufferPass(const gl::GlApi& gl, gl::ShaderProgram mesh, gl::ShaderProgram patch, gl::ShaderProgram quadric,
                    gl::ShaderProgram partLayer)
      : mesh_(std::move(mesh)),
        patch_(std::move(patch)),
        quadric_(std::move(quadric)),
        partLayer_(std::move(partLayer)),
        emptyVertexArray_(gl) {}
  // Draws the mirror of `planned` into the attached colour targets over `rect`, the depth test keeping the nearest.
  void drawMirror(const FrameContext& frame, const PlannedMirror& planned, const TexelRect& rect) const;
  // Attach the colour targets and return how many there are: the scratch textures ((re)allocated to
  // the G-buffer's size and format), or one layer's.
  int attachScratch(const FrameContext& frame);
  int attachLayer(const FrameContext& frame, int layer, bool parametric) const;

  gl::ShaderProgram mesh_;       // the mirror's (search) mesh
  gl::ShaderProgram patch_;      // a parametric mesh tessellated for the view, each texel on its exact patch
  gl::ShaderProgram quadric_;    // an exact quadric inside its proxy box
  gl::ShaderProgram partLayer_;  // one part's layer from the scratch textures
  gl::GlVertexArray emptyVertexArray_;
  std::optional<Scratch> scratch_;  // made for the first mirror of several parts
};

}  // namespace specula::passes
