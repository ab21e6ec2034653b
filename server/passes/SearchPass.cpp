#include "passes/SearchPass.h"

#include <algorithm>

#include "passes/ExplosionMapPass.h"
#include "passes/QuadricUniforms.h"
#include "passes/ReflectedVertex.h"

namespace specula::passes {

namespace {
constexpr GLuint kGroupSize = 64;  // local_size_x of search.comp
// Texels a cold start scans along the mirror's longer side, at most, and the coarse texels it climbs
// from: a closed convex mirror has one best point, other parts may have several local ones.
constexpr int kConvexColdScanSide = 8, kColdScanSide = 16;
constexpr int kConvexColdCandidates = 1, kColdCandidates = 3;
constexpr GLuint kSearchPatchPointsBinding = 11;  // PATCH_POINTS_BINDING in search/patch-newton.glsl
}  // namespace

Result<std::unique_ptr<SearchPass>> SearchPass::create(const gl::GlApi& gl) {
  auto program = gl::ShaderProgram::build(gl, {"search/search.comp"});
  if (!program) return Error{program.error()};
  return std::unique_ptr<SearchPass>(new SearchPass(std::move(program.value())));
}

void setSearchUniforms(const gl::ShaderProgram& program, const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  bindGBufferTextures(gl, frame.reflections);
  // A strategy's texture arrays on their own units (2 and up; the G-buffer holds 0 and 1).
  const auto bindArray = [&](GLuint unit, GLuint texture, const char* sampler) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, texture);
    program.set(sampler, static_cast<int>(unit));
  };
  const bool hierarchy = frame.settings.search == SearchStrategy::Hierarchy;
  if (hierarchy) {
    bindArray(2, frame.reflections.rayHierarchySpheres(), "rayHierarchySpheres");
    bindArray(3, frame.reflections.rayHierarchyCones(), "rayHierarchyCones");
    program.set("rayHierarchyTop", frame.reflections.rayHierarchyTopLevel());
  }
  const bool explosionMap = frame.settings.search == SearchStrategy::ExplosionMap;
  if (explosionMap) {
    bindArray(4, frame.reflections.explosionPositions(), "explosionPositions");
    bindArray(5, frame.reflections.explosionNormals(), "explosionNormals");
  }
  program.set("gbufferWorldToClip", frame.gbufferWorldToClip());
  program.set("explosionMap", explosionMap ? 1 : 0);
  program.set("explosionRefine", explosionMap && frame.settings.explosionRefine ? 1 : 0);
  program.set("explosionMirrorPlacement", frame.settings.explosionMirrorPlacement ? 1 : 0);
  gl.ActiveTexture(GL_TEXTURE0);
  program.set("rayHierarchy", hierarchy ? 1 : 0);
  setGBufferSamplers(program);
  program.set("gbufferSurface", static_cast<int>(kGBufferSurfaceUnit));
  program.set("eyePosition", frame.pose.camera.eye);
  program.set("maxWalkSteps", frame.settings.maxWalkSteps);
}

void setSearchMirror(const gl::ShaderProgram& program, const FrameContext& frame, const MirrorSlots& mirror) {
  program.set("layer", mirror.layer);
  // The cold start scans the mirror's texels at the finest level where they span at most the scan side.
  const bool closedConvex = mirror.partCount == 1 && mirror.kind == scene::SurfaceKind::Convex &&
                            frame.scene.objects[mirror.mirrorObject].mirror->closed;
  const int side = closedConvex ? kConvexColdScanSide : kColdScanSide;
  const TexelRect& covered = frame.reflections.coveredRect(mirror.layer);
  int level = 0;
  while (level < frame.reflections.coarseLevel() &&
         std::max(covered.high.x - covered.low.x, covered.high.y - covered.low.y) > (side << level))
    ++level;
  program.set("coldCandidates", closedConvex ? kConvexColdCandidates : kColdCandidates);
  program.set("coarseLevel", level);
  program.set("coarseRect", glm::ivec4(covered.low >> level, ((covered.high - 1) >> level) + 1));
  const scene::MirrorInfo& info = *frame.scene.objects[mirror.mirrorObject].mirror;
  setMirrorQuadric(program, info, frame.pose.objectToWorld[mirror.mirrorObject]);
  setMirrorExtrusion(program, info, frame.pose.objectToWorld[mirror.mirrorObject], frame.settings.solveExtrusions);
  const std::size_t searchMesh = frame.searchMesh(mirror.mirrorObject);
  const bool parametric = !frame.scene.meshes[searchMesh].patches.empty();
  program.set("exactGBuffer", parametric ? 1 : 0);
  if (parametric) {
    program.set("patchObjectToWorld", frame.pose.objectToWorld[mirror.mirrorObject]);
    frame.gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSearchPatchPointsBinding,
                            frame.meshes.patchPointsBuffer(searchMesh));
  }
  if (frame.settings.search == SearchStrategy::ExplosionMap) setExplosionMapFrame(program, frame, mirror);
}

std::optional<std::string> searchLimitProblem(const gl::GlApi& gl, const scene::Scene& scene,
                                              const ReflectionSlots& slots) {
  GLint64 maxStorageBytes = 0;
  GLint maxGroups = 0;
  gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxStorageBytes);
  gl.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &maxGroups);
  const auto mebibytes = [](std::uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; };
  const std::string limit = "this GL allows " + mebibytes(static_cast<std::uint64_t>(maxStorageBytes)) +
                            " of shader storage per buffer and " + std::to_string(maxGroups) +
                            " work groups per dispatch";
  const std::uint64_t slotBytes = std::uint64_t{slots.slotCount} * sizeof(ReflectedVertex);
  if (slotBytes > static_cast<std::uint64_t>(maxStorageBytes))
    return "scene '" + scene.name + "' needs " + std::to_string(slots.slotCount) + " reflection slots (" +
           mebibytes(slotBytes) + ", mirrors × reflected vertices); " + limit +
           ": set \"reflected\": false on objects no mirror needs to show, "
           "or use fewer mirrors or a GPU with larger limits";
  for (const MirrorSlots& mirror : slots.mirrors)
    for (const ReflectionSlotRange& range : mirror.reflected) {
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      const std::uint64_t bytes = mesh.vertices.size() * sizeof(scene::Vertex);
      const std::uint64_t groups = (mesh.vertices.size() + kGroupSize - 1) / kGroupSize;
      if (bytes > static_cast<std::uint64_t>(maxStorageBytes) || groups > static_cast<std::uint64_t>(maxGroups))
        return "mesh '" + mesh.name + "' of scene '" + scene.name + "' has " + std::to_string(mesh.vertices.size()) +
               " vertices (" + mebibytes(bytes) + ", " + std::to_string(groups) + " work groups) to search; " + limit +
               ": split the mesh, set \"reflected\": false on its object, or use a GPU with larger limits";
    }
  return std::nullopt;
}

void SearchPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  resources.resetStatistics();
  program_.use();
  setSearchUniforms(program_, frame);
  program_.set("useCoherence", frame.settings.coherence ? 1 : 0);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, resources.reflectedVertices());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, resources.statistics());

  for (const PlannedMirror& mirror : frame.plan.mirrors) {
    if (mirror.method != PartMethod::VirtualObjects) continue;
    setSearchMirror(program_, frame, *mirror.slots);
    for (const ReflectionSlotRange* range : mirror.reflected) {
      const scene::SceneObject& object = frame.scene.objects[range->object];
      const auto vertexCount = static_cast<GLuint>(frame.scene.meshes[object.mesh].vertices.size());
      if (vertexCount == 0) continue;
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, frame.meshes.vertexBuffer(object.mesh));
      // Not setReflectedObject: the search reads no normals, so its program has no normalToWorld.
      program_.set("objectToWorld", frame.pose.objectToWorld[range->object]);
      program_.set("firstSlot", static_cast<unsigned>(range->firstSlot));
      program_.set("vertexCount", static_cast<unsigned>(vertexCount));
      gl.DispatchCompute((vertexCount + kGroupSize - 1) / kGroupSize, 1, 1);
    }
  }
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace specula::passes
