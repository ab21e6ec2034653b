#pragma once
// Meshes that change shape, on the GPU: every frame, before any pass reads them, the objects whose morph
// target weights animate or whose skin's joints move get their mesh's vertices as the pose shapes them
// (shaders/deform/deform.comp), written into GpuMeshes' vertex buffer that every pass reads; and a
// hierarchy cast against such a mesh is refitted to its new shape. One object a deforming mesh (the
// importer gives each its own).
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "gl/ShaderProgram.h"
#include "math/Bounds.h"
#include "passes/GpuMeshes.h"
#include "passes/MeshBvh.h"
#include "scene/Deformation.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::passes {

class GpuDeformation {
 public:
  static Result<GpuDeformation> create(const gl::GlApi& gl, const scene::Scene& scene);

  // Writes every deforming mesh of `meshes` (the scene's) whose weights or joints differ from those it
  // was last written with, as `pose` has them; returns whether it wrote any.
  bool apply(const scene::ScenePose& pose, const GpuMeshes& meshes);
  bool deforms(std::uint32_t mesh) const { return meshes_.contains(mesh); }
  // A box holding deforming mesh `mesh` (object space) as `pose` shapes it.
  math::Bounds bounds(std::uint32_t mesh, const scene::ScenePose& pose) const;
  // Refits `bvh`, built over deforming mesh `mesh`, to the shape the mesh has now, if it is not at it yet.
  void refit(MeshBvh& bvh, std::uint32_t mesh, const GpuMeshes& meshes) const;

 private:
  struct Deforming {
    std::uint32_t object = 0;
    GLuint vertexCount = 0, triangleCount = 0, targetCount = 0, influenceSets = 0;
    gl::GlBuffer rest, displacements, weights, influences, joints;
    scene::DeformationExtents extents;
    std::vector<float> restWeights;
    std::vector<glm::mat4> restJoints;
    std::vector<float> writtenWeights;  // what the vertex buffer holds; both empty before the first frame
    std::vector<glm::mat4> writtenJoints;
    bool written = false;
    std::uint64_t shape = 0;  // counts the shapes written; a refitted hierarchy records the one it fits
  };
  struct Programs {
    gl::ShaderProgram deform, refitTriangles, refitNodes;
  };
  // The pose's weights and joints for the entry's object; its rest ones where the pose has none (a pose
  // made by hand).
  static std::span<const float> weightsAt(const scene::ScenePose& pose, const Deforming& entry);
  static std::span<const glm::mat4> jointsAt(const scene::ScenePose& pose, const Deforming& entry);
  GpuDeformation(const gl::GlApi& gl, std::optional<Programs> programs) : gl_(&gl), programs_(std::move(programs)) {}

  const gl::GlApi* gl_;
  std::optional<Programs> programs_;  // only when something deforms
  std::map<std::uint32_t, Deforming> meshes_;
};

}  // namespace specula::passes
