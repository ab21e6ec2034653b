#include "passes/PatchTessellation.h"

#include <algorithm>
#include <cstdint>

#include "math/Transform.h"

namespace specula::passes {

namespace {
constexpr GLuint kAreasBinding = 2;  // shaders/common/patch-triangle-areas.geom
}

void setPatchView(const gl::ShaderProgram& program, const glm::mat4& objectToWorld, const glm::mat4& worldToClip,
                  glm::ivec2 viewportPixels) {
  program.set("objectToWorld", objectToWorld);
  program.set("normalToWorld", math::normalMatrix(objectToWorld));
  program.set("worldToClip", worldToClip);
  program.set("viewportPixels", glm::vec2(viewportPixels));
}

Result<PatchTessellationProbe> PatchTessellationProbe::create(const gl::GlApi& gl) {
  auto program = gl::ShaderProgram::build(gl, {"common/bezier-patch.vert", "common/bezier-patch.tesc",
                                               "common/bezier-patch.tese", "common/patch-triangle-areas.geom"});
  if (!program) return Error{program.error()};
  return PatchTessellationProbe(gl, std::move(program.value()));
}

PatchTessellationMeasure PatchTessellationProbe::measure(const scene::Scene& scene, const scene::ScenePose& pose,
                                                         const GpuMeshes& meshes, const glm::mat4& worldToClip,
                                                         glm::ivec2 viewportPixels) {
  const gl::GlApi& gl = *gl_;
  PatchTessellationMeasure measure;
  // Room for the finest tessellation of every patch (64 × 64 quads), so no area is lost.
  std::size_t finest = 0;
  for (const scene::SceneObject& object : scene.objects)
    finest += scene.meshes[object.mesh].patches.size() * 2 * 64 * 64;
  if (finest == 0) return measure;
  if (finest > capacity_) {
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, areas_.id());
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>((finest + 1) * sizeof(float)), nullptr,
                  GL_DYNAMIC_READ);
    capacity_ = finest;
  }
  const std::uint32_t zero = 0;
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, areas_.id());
  gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zero), &zero);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kAreasBinding, areas_.id());
  gl.Enable(GL_RASTERIZER_DISCARD);
  program_.use();
  program_.set("capacity", static_cast<unsigned>(capacity_));
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const std::size_t mesh = scene.objects[i].mesh;
    if (scene.meshes[mesh].patches.empty()) continue;
    measure.patches += scene.meshes[mesh].patches.size();
    setPatchView(program_, pose.objectToWorld[i], worldToClip, viewportPixels);
    meshes.drawPatches(mesh);
  }
  gl.Disable(GL_RASTERIZER_DISCARD);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t count = 0;
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, areas_.id());
  gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(count), &count);
  measure.triangles = count;
  std::vector<float> areas(std::min<std::size_t>(count, capacity_));
  if (!areas.empty())
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, sizeof(float), static_cast<GLsizeiptr>(areas.size() * sizeof(float)),
                        areas.data());
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  for (const float area : areas)
    if (area >= 0.0f) measure.pixelAreas.push_back(area);
  return measure;
}

}  // namespace specula::passes
