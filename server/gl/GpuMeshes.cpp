#include "gl/GpuMeshes.h"

#include <cstddef>

namespace specula::gl {

GpuMeshes::GpuMeshes(const GlApi& gl, const std::vector<scene::Mesh>& meshes) : gl_(&gl) {
  meshes_.reserve(meshes.size());
  for (const scene::Mesh& mesh : meshes) {
    Entry entry{GlVertexArray(gl), GlBuffer(gl), GlBuffer(gl), static_cast<GLsizei>(mesh.indices.size())};
    gl.BindVertexArray(entry.vertexArray.id());
    gl.BindBuffer(GL_ARRAY_BUFFER, entry.vertices.id());
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(scene::Vertex)),
                  mesh.vertices.data(), GL_STATIC_DRAW);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, entry.indices.id());
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                  mesh.indices.data(), GL_STATIC_DRAW);
    constexpr auto stride = static_cast<GLsizei>(sizeof(scene::Vertex));
    gl.EnableVertexAttribArray(kPositionLocation);
    gl.VertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(offsetof(scene::Vertex, position)));
    gl.EnableVertexAttribArray(kNormalLocation);
    gl.VertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(offsetof(scene::Vertex, normal)));
    gl.EnableVertexAttribArray(kUvLocation);
    gl.VertexAttribPointer(kUvLocation, 2, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(offsetof(scene::Vertex, uv)));
    meshes_.push_back(std::move(entry));
  }
  gl.BindVertexArray(0);
}

void GpuMeshes::draw(std::size_t index) const {
  const Entry& entry = meshes_.at(index);
  gl_->BindVertexArray(entry.vertexArray.id());
  gl_->DrawElements(GL_TRIANGLES, entry.indexCount, GL_UNSIGNED_INT, nullptr);
}

}  // namespace specula::gl
