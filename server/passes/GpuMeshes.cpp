#include "passes/GpuMeshes.h"

#include <cstddef>
#include <glm/glm.hpp>

namespace specula::passes {

GpuMeshes::GpuMeshes(const gl::GlApi& gl, const std::vector<scene::Mesh>& meshes) : gl_(&gl) {
  meshes_.reserve(meshes.size());
  for (const scene::Mesh& mesh : meshes) {
    Entry entry{gl::GlVertexArray(gl), gl::GlBuffer(gl),
                gl::GlBuffer(gl),      static_cast<GLsizei>(mesh.indices.size()),
                std::nullopt,          0};
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
    if (!mesh.patches.empty()) {
      std::vector<glm::vec4> points;
      for (const math::BezierPatch& patch : mesh.patches)
        for (const glm::dvec3& point : patch.points) points.emplace_back(glm::vec3(point), 1.0f);
      entry.patchPoints.emplace(gl);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, entry.patchPoints->id());
      gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(points.size() * sizeof(glm::vec4)), points.data(),
                    GL_STATIC_DRAW);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
      entry.patchCount = static_cast<GLsizei>(mesh.patches.size());
    }
    meshes_.push_back(std::move(entry));
  }
  gl.BindVertexArray(0);
}

void GpuMeshes::draw(std::size_t index) const {
  const Entry& entry = meshes_.at(index);
  gl_->BindVertexArray(entry.vertexArray.id());
  gl_->DrawElements(GL_TRIANGLES, entry.indexCount, GL_UNSIGNED_INT, nullptr);
}

void GpuMeshes::drawIndirect(std::size_t index, GLintptr offset) const {
  gl_->BindVertexArray(meshes_.at(index).vertexArray.id());
  gl_->DrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset));
}

void GpuMeshes::drawPatches(std::size_t index) const {
  const Entry& entry = meshes_.at(index);
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, kPatchPointsBinding, entry.patchPoints.value().id());
  gl_->BindVertexArray(entry.vertexArray.id());  // core GL draws nothing without a vertex array
  gl_->PatchParameteri(GL_PATCH_VERTICES, 1);
  gl_->DrawArrays(GL_PATCHES, 0, entry.patchCount);
}

}  // namespace specula::passes
