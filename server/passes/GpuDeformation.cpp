#include "passes/GpuDeformation.h"

#include <algorithm>
#include <glm/glm.hpp>

namespace specula::passes {

namespace {

constexpr GLuint kGroupSize = 64;  // local_size_x of the deform and refit shaders

GLuint groups(GLuint count) { return (count + kGroupSize - 1) / kGroupSize; }

template <class T>
void store(const gl::GlApi& gl, const gl::GlBuffer& buffer, std::span<const T> data, GLenum usage) {
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(data.size(), 1) * sizeof(T)),
                data.empty() ? nullptr : data.data(), usage);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

// std430 twin of Influences in deform.comp.
struct GpuInfluences {
  glm::uvec4 joints;
  glm::vec4 weights;
};

}  // namespace

Result<GpuDeformation> GpuDeformation::create(const gl::GlApi& gl, const scene::Scene& scene) {
  if (scene.rig.morphed.empty() && scene.rig.skinned.empty()) return GpuDeformation(gl, std::nullopt);
  auto deform = gl::ShaderProgram::build(gl, {"deform/deform.comp"});
  if (!deform) return Error{deform.error()};
  auto refitTriangles = gl::ShaderProgram::build(gl, {"deform/bvh-refit-triangles.comp"});
  if (!refitTriangles) return Error{refitTriangles.error()};
  auto refitNodes = gl::ShaderProgram::build(gl, {"deform/bvh-refit-nodes.comp"});
  if (!refitNodes) return Error{refitNodes.error()};
  GpuDeformation deformation(
      gl, Programs{std::move(deform.value()), std::move(refitTriangles.value()), std::move(refitNodes.value())});
  // Every deforming object with its rest weights and, for a skinned one, the joints of the rest pose.
  const std::vector<glm::dmat4> restWorld = scene.rig.worldAt(0.0);
  const std::vector<std::vector<glm::mat4>> restJoints = scene.rig.jointMatrices(restWorld);
  std::map<std::uint32_t, std::pair<std::vector<float>, std::vector<glm::mat4>>> deforming;
  for (const scene::MorphedObject& morphed : scene.rig.morphed) deforming[morphed.object].first = morphed.restWeights;
  for (std::size_t s = 0; s < scene.rig.skinned.size(); ++s)
    deforming[scene.rig.skinned[s].object].second = restJoints[s];
  for (const auto& [object, rest] : deforming) {
    const std::uint32_t index = scene.objects[object].mesh;
    const scene::Mesh& mesh = scene.meshes[index];
    Deforming entry{object,
                    static_cast<GLuint>(mesh.vertices.size()),
                    static_cast<GLuint>(mesh.triangleCount()),
                    static_cast<GLuint>(mesh.morphTargets.size()),
                    static_cast<GLuint>(rest.second.empty() ? 0 : mesh.influences.size()),
                    gl::GlBuffer(gl),
                    gl::GlBuffer(gl),
                    gl::GlBuffer(gl),
                    gl::GlBuffer(gl),
                    gl::GlBuffer(gl),
                    scene::deformationExtents(mesh, rest.second.size()),
                    rest.first,
                    rest.second,
                    {},
                    {},
                    false,
                    0};
    std::vector<glm::vec4> displacements;
    displacements.reserve(2 * mesh.vertices.size() * mesh.morphTargets.size());
    for (const scene::MorphTarget& target : mesh.morphTargets)
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        displacements.emplace_back(target.positions[v], 0.0f);
        displacements.emplace_back(target.normals.empty() ? glm::vec3(0.0f) : target.normals[v], 0.0f);
      }
    std::vector<GpuInfluences> influences;
    for (std::size_t s = 0; s < entry.influenceSets; ++s)
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        influences.push_back({mesh.influences[s].joints[v], mesh.influences[s].weights[v]});
    store(gl, entry.rest, std::span<const scene::Vertex>(mesh.vertices), GL_STATIC_DRAW);
    store(gl, entry.displacements, std::span<const glm::vec4>(displacements), GL_STATIC_DRAW);
    store(gl, entry.influences, std::span<const GpuInfluences>(influences), GL_STATIC_DRAW);
    store(gl, entry.weights, std::span<const float>(entry.restWeights), GL_DYNAMIC_DRAW);
    store(gl, entry.joints, std::span<const glm::mat4>(entry.restJoints), GL_DYNAMIC_DRAW);
    deformation.meshes_.emplace(index, std::move(entry));
  }
  return deformation;
}

std::span<const float> GpuDeformation::weightsAt(const scene::ScenePose& pose, const Deforming& entry) {
  const bool posed = entry.object < pose.morphWeights.size() && !pose.morphWeights[entry.object].empty();
  return posed ? std::span<const float>(pose.morphWeights[entry.object]) : std::span<const float>(entry.restWeights);
}

std::span<const glm::mat4> GpuDeformation::jointsAt(const scene::ScenePose& pose, const Deforming& entry) {
  const bool posed = entry.object < pose.jointMatrices.size() && !pose.jointMatrices[entry.object].empty();
  return posed ? std::span<const glm::mat4>(pose.jointMatrices[entry.object])
               : std::span<const glm::mat4>(entry.restJoints);
}

math::Bounds GpuDeformation::bounds(std::uint32_t mesh, const scene::ScenePose& pose) const {
  const Deforming& entry = meshes_.at(mesh);
  return scene::deformedBounds(entry.extents, weightsAt(pose, entry), jointsAt(pose, entry));
}

bool GpuDeformation::apply(const scene::ScenePose& pose, const GpuMeshes& meshes) {
  if (!programs_) return false;
  bool used = false;
  for (auto& [mesh, entry] : meshes_) {
    const std::span<const float> weights = weightsAt(pose, entry);
    const std::span<const glm::mat4> joints = jointsAt(pose, entry);
    if (entry.written && std::ranges::equal(weights, entry.writtenWeights) &&
        std::ranges::equal(joints, entry.writtenJoints))
      continue;
    if (!used) programs_->deform.use();
    used = true;
    // Sizes were fixed at creation: the pose's lists have the rest lists' lengths (sceneProblem, jointMatrices).
    gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, entry.weights.id());
    gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(weights.size_bytes()), weights.data());
    gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, entry.joints.id());
    gl_->BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(joints.size_bytes()), joints.data());
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, entry.rest.id());
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, entry.displacements.id());
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, entry.weights.id());
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, meshes.vertexBuffer(mesh));
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, entry.influences.id());
    gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, entry.joints.id());
    programs_->deform.set("vertexCount", entry.vertexCount);
    programs_->deform.set("targetCount", entry.targetCount);
    programs_->deform.set("influenceSets", entry.influenceSets);
    gl_->DispatchCompute(groups(entry.vertexCount), 1, 1);
    entry.writtenWeights.assign(weights.begin(), weights.end());
    entry.writtenJoints.assign(joints.begin(), joints.end());
    entry.written = true;
    ++entry.shape;
  }
  if (!used) return false;
  gl_->BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // Every later reader: vertex fetch, compute passes' storage reads, the refit.
  gl_->MemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  return true;
}

void GpuDeformation::refit(MeshBvh& bvh, std::uint32_t mesh, const GpuMeshes& meshes) const {
  const Deforming& entry = meshes_.at(mesh);
  if (bvh.shape == entry.shape || bvh.levels.empty()) return;
  programs_->refitTriangles.use();
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, meshes.vertexBuffer(mesh));
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, meshes.indexBuffer(mesh));
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, bvh.triangles.id());
  programs_->refitTriangles.set("triangleCount", entry.triangleCount);
  gl_->DispatchCompute(groups(entry.triangleCount), 1, 1);
  gl_->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  programs_->refitNodes.use();
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bvh.nodes.id());
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, bvh.triangles.id());
  gl_->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, bvh.levelOrder->id());
  for (const MeshBvh::Level& level : bvh.levels) {  // deepest first: children before their parents
    programs_->refitNodes.set("firstInLevel", level.first);
    programs_->refitNodes.set("levelSize", level.size);
    gl_->DispatchCompute(groups(level.size), 1, 1);
    gl_->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  bvh.shape = entry.shape;
}

}  // namespace specula::passes
