#pragma once
// The scene's meshes in GL buffers, uploaded once and drawn by index. One VAO per mesh; a
// parametric mesh also keeps its Bézier patches' control points for the tessellation shaders.
#include <optional>
#include <vector>

#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "scene/Scene.h"

namespace specula::passes {

class GpuMeshes {
 public:
  // Vertex attribute locations every pass's vertex shader uses.
  static constexpr GLuint kPositionLocation = 0, kNormalLocation = 1, kUvLocation = 2;
  // Storage binding of a parametric mesh's control points (16 vec4 a patch, object space).
  static constexpr GLuint kPatchPointsBinding = 1;

  GpuMeshes(const gl::GlApi& gl, const std::vector<scene::Mesh>& meshes);

  // Draws all triangles of mesh `index` with the program and state currently bound.
  void draw(std::size_t index) const;
  // Draws mesh `index` by the DrawElementsIndirectCommand at `offset` of the bound
  // GL_DRAW_INDIRECT_BUFFER (the GPU decides whether it is drawn: its instance count).
  void drawIndirect(std::size_t index, GLintptr offset) const;
  // Draws mesh `index`'s Bézier patches, one GL patch of one vertex each (the tessellation shaders
  // read patch gl_PrimitiveID's control points from kPatchPointsBinding), with the program bound.
  void drawPatches(std::size_t index) const;
  // A parametric mesh's control points buffer, for shaders that bind it themselves.
  GLuint patchPointsBuffer(std::size_t index) const { return meshes_.at(index).patchPoints.value().id(); }
  std::size_t size() const { return meshes_.size(); }
  // The mesh's vertex buffer (scene::Vertex records), for compute passes that read it as storage.
  GLuint vertexBuffer(std::size_t index) const { return meshes_.at(index).vertices.id(); }
  // Its index buffer (three uint32 per triangle), likewise.
  GLuint indexBuffer(std::size_t index) const { return meshes_.at(index).indices.id(); }

 private:
  struct Entry {
    gl::GlVertexArray vertexArray;
    gl::GlBuffer vertices;
    gl::GlBuffer indices;
    GLsizei indexCount;
    std::optional<gl::GlBuffer> patchPoints;  // parametric meshes only
    GLsizei patchCount = 0;
  };
  const gl::GlApi* gl_;
  std::vector<Entry> meshes_;
};

}  // namespace specula::passes
