#include "passes/TessellationPass.h"

#include <cstddef>

#include "passes/SearchPass.h"

namespace specula::passes {

namespace {
static_assert(kMaxTessellationLevel < TESSELLATION_MAX_ROUNDS, "the run records hold a draw per round");

GLuint groupsFor(std::size_t invocations) {
  return static_cast<GLuint>((invocations + TESSELLATION_GROUP_SIZE - 1) / TESSELLATION_GROUP_SIZE);
}

// Byte offsets in a run record of its round's indirect dispatch over triangles and over searches.
std::size_t workGroupsOffset(int parity) {
  return offsetof(gpu::TessellationRun, work) + static_cast<std::size_t>(parity) * sizeof(gpu::RunWork) + offsetof(gpu::RunWork, groups);
}
constexpr std::size_t kSearchGroupsOffset = offsetof(gpu::TessellationRun, searchGroups);
}  // namespace

Result<std::unique_ptr<TessellationPass>> TessellationPass::create(const gl::GlApi& gl) {
  const auto build = [&](std::string_view file) { return gl::ShaderProgram::build(gl, {file}); };
  auto classify = build("tessellation/tessellation-classify.comp");
  if (!classify) return Error{classify.error()};
  auto dispatch = build("tessellation/tessellation-dispatch.comp");
  if (!dispatch) return Error{dispatch.error()};
  auto search = build("tessellation/tessellation-search.comp");
  if (!search) return Error{search.error()};
  auto decide = build("tessellation/tessellation-decide.comp");
  if (!decide) return Error{decide.error()};
  auto layout = build("tessellation/tessellation-layout.comp");
  if (!layout) return Error{layout.error()};
  auto emit = build("tessellation/tessellation-emit.comp");
  if (!emit) return Error{emit.error()};
  return std::unique_ptr<TessellationPass>(new TessellationPass(Programs{std::move(*classify), std::move(*dispatch), std::move(*search),
                                                                         std::move(*decide), std::move(*layout), std::move(*emit)}));
}

std::vector<TessellationPass::PartRuns> TessellationPass::beginRuns(const FrameContext& frame) const {
  std::vector<PartRuns> parts;
  std::vector<TessellatedRun> runs;
  std::vector<gpu::TessellationRun> records;
  std::vector<gpu::RunDraws> draws;
  std::size_t largestPart = 0;
  for (std::size_t planIndex = 0; planIndex < frame.plan.mirrors.size(); ++planIndex) {
    const PlannedMirror& planned = frame.plan.mirrors[planIndex];
    if (planned.method != PartMethod::VirtualObjects) continue;
    PartRuns part{planIndex, runs.size(), 0};
    std::uint32_t partTriangles = 0;  // round 0 numbers the part's mesh triangles run after run
    for (std::size_t i = 0; i < planned.reflected.size(); ++i) {
      const ReflectionSlotRange* range = planned.reflected[i];
      if (range->triangleCount == 0) continue;
      const auto triangles = static_cast<std::uint32_t>(range->triangleCount);
      // An object the plan predicts unsplit (PlannedMirror::tessellated) is drawn from its mesh with no round.
      const bool rounds = planned.tessellated[i];
      gpu::TessellationRun record{};
      gpu::RunDraws draw{};
      draw.mesh = {3 * triangles, rounds ? 0u : 1u, 0, 0, 0};
      for (gpu::DrawArraysCommand& round : draw.rounds) round = {0, 1, 0, 0};
      if (rounds) {
        record.work[0] = {partTriangles, triangles, {groupsFor(triangles), 1, 1}};
        partTriangles += triangles;
      } else {
        record.drawnFromMesh = 1;
      }
      runs.push_back({planned.slots, range, rounds});
      records.push_back(record);
      draws.push_back(draw);
    }
    part.runCount = runs.size() - part.firstRun;
    largestPart = std::max<std::size_t>(largestPart, partTriangles);
    if (partTriangles > 0) parts.push_back(part);
  }
  frame.reflections.tessellation().beginFrame(std::move(runs), records, draws, largestPart);
  return parts;
}

void TessellationPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  const std::vector<PartRuns> parts = beginRuns(frame);
  const TessellationBuffers& buffers = frame.reflections.tessellation();
  const TessellationSettings& settings = frame.settings.tessellation;
  for (const gl::ShaderProgram* program : {&programs_.classify, &programs_.search, &programs_.decide, &programs_.emit}) {
    program->use();
    program->set("crackFree", settings.mode == TessellationMode::CrackFree ? 1 : 0);
    program->set("pixelMetric", settings.metric == TessellationMetric::Pixels ? 1 : 0);
    program->set("threshold", settings.threshold);
    program->set("frameWorldToClip", frame.view.worldToClip());
    program->set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
  }
  for (const gl::ShaderProgram* program : {&programs_.classify, &programs_.search}) {
    program->use();
    setSearchUniforms(*program, frame);
  }
  programs_.layout.use();
  programs_.layout.set("maxTriangles", static_cast<unsigned>(TessellationBuffers::kMaxTriangles));
  programs_.layout.set("workingCapacity", static_cast<unsigned>(buffers.workingCapacity()));
  programs_.layout.set("finishedCapacity", static_cast<unsigned>(buffers.finishedCapacity()));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_SEARCH_STATISTICS_BINDING, buffers.midpointStatistics());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_SPLITS_BINDING, buffers.splits());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_TOTALS_BINDING, buffers.totals());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_REQUESTS_BINDING, buffers.requests());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_RUNS_BINDING, buffers.runs());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_FINISHED_BINDING, buffers.finished());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_DRAWS_BINDING, buffers.draws());
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffers.runs());
  for (const PartRuns& part : parts) tessellatePart(frame, part);
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

void TessellationPass::tessellatePart(const FrameContext& frame, const PartRuns& part) const {
  const gl::GlApi& gl = frame.gl;
  const TessellationBuffers& buffers = frame.reflections.tessellation();
  const PlannedMirror& planned = frame.plan.mirrors[part.planIndex];
  const MirrorSlots& mirror = *planned.slots;
  for (const gl::ShaderProgram* program : {&programs_.classify, &programs_.search}) {
    program->use();
    setSearchMirror(*program, frame, mirror);
  }
  programs_.classify.use();
  programs_.classify.set("mirrorRect", frame.reflections.coveredFramePixels(mirror.layer));
  const math::Bounds& bounds = frame.worldBounds[mirror.mirrorObject];
  programs_.classify.set("mirrorSphere", glm::vec4(bounds.center(), bounds.radius()));
  programs_.classify.set("everyCornerReflected", mirror.kind == scene::SurfaceKind::Convex ? 0 : 1);
  programs_.dispatch.use();
  programs_.dispatch.set("firstRun", static_cast<unsigned>(part.firstRun));
  programs_.dispatch.set("runCount", static_cast<unsigned>(part.runCount));
  programs_.layout.use();
  programs_.layout.set("firstRun", static_cast<unsigned>(part.firstRun));
  programs_.layout.set("runCount", static_cast<unsigned>(part.runCount));
  programs_.layout.set("partsLeft", static_cast<unsigned>(frame.plan.mirrors.size() - part.planIndex));

  const int maxLevel = frame.settings.tessellation.maxLevel;
  for (int round = 0; round <= maxLevel; ++round) {
    const int parity = round % 2;
    // Working lists ping-pong: round 0 reads the meshes and writes list 0, round r reads list
    // (r − 1) % 2 and writes the other.
    if (round > 0) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_WORKING_BINDING, buffers.working((round + 1) % 2));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_NEXT_WORKING_BINDING, buffers.working(round % 2));
    const std::size_t triangleGroups = workGroupsOffset(parity);
    if (round < maxLevel) {
      dispatchRuns(frame, programs_.classify, part, round, triangleGroups);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      programs_.dispatch.use();
      gl.DispatchCompute(groupsFor(part.runCount), 1, 1);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
      dispatchRuns(frame, programs_.search, part, round, kSearchGroupsOffset);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      dispatchRuns(frame, programs_.decide, part, round, triangleGroups);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    programs_.layout.use();
    programs_.layout.set("round", static_cast<unsigned>(round));
    programs_.layout.set("parity", static_cast<unsigned>(parity));
    programs_.layout.set("lastRound", round == maxLevel ? 1 : 0);
    gl.DispatchCompute(1, 1, 1);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    dispatchRuns(frame, programs_.emit, part, round, triangleGroups);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  }
}

void TessellationPass::dispatchRuns(const FrameContext& frame, const gl::ShaderProgram& program, const PartRuns& part, int round,
                                    std::size_t indirectOffset) const {
  const gl::GlApi& gl = frame.gl;
  const std::vector<TessellatedRun>& runs = frame.reflections.tessellation().frameRuns();
  const bool fromMesh = round == 0;
  program.use();
  program.set("fromMesh", fromMesh ? 1 : 0);
  program.set("parity", static_cast<unsigned>(round % 2));
  for (std::size_t i = part.firstRun; i < part.firstRun + part.runCount; ++i) {
    const TessellatedRun& run = runs[i];
    if (!run.rounds) continue;
    program.set("runIndex", static_cast<unsigned>(i));
    // Round 0's triangles are the mesh's, known here; the search's requests are counted on the GPU.
    if (fromMesh) {
      const std::size_t mesh = frame.scene.objects[run.object->object].mesh;
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_MESH_VERTICES_BINDING, frame.meshes.vertexBuffer(mesh));
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_MESH_INDICES_BINDING, frame.meshes.indexBuffer(mesh));
      frame.setReflectedObject(program, *run.object);
    }
    if (fromMesh && indirectOffset != kSearchGroupsOffset)
      gl.DispatchCompute(groupsFor(run.object->triangleCount), 1, 1);
    else
      gl.DispatchComputeIndirect(static_cast<GLintptr>(i * sizeof(gpu::TessellationRun) + indirectOffset));
  }
}

}  // namespace specula::passes
