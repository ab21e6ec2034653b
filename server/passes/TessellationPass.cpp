#include "passes/TessellationPass.h"

#include <cstddef>

#include "passes/SearchPass.h"

namespace specula::passes {

namespace {
static_assert(kMaxTessellationLevel < TESSELLATION_MAX_ROUNDS, "the run records hold a draw per round");

GLuint groupsFor(std::size_t invocations) {
  return static_cast<GLuint>((invocations + TESSELLATION_GROUP_SIZE - 1) / TESSELLATION_GROUP_SIZE);
}

// Byte offsets of the indirect dispatches a later round launches: in the totals, over the part's
// triangles and over its searches; in a run record, round 0's search of that run.
std::size_t partGroupsOffset(int parity) {
  return offsetof(gpu::TessellationTotals, part) + static_cast<std::size_t>(parity) * sizeof(gpu::PartWork) +
         offsetof(gpu::PartWork, groups);
}
constexpr std::size_t kPartSearchGroupsOffset = offsetof(gpu::TessellationTotals, partSearchGroups);
constexpr std::size_t kRunSearchGroupsOffset = offsetof(gpu::TessellationRun, searchGroups);
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
  return std::unique_ptr<TessellationPass>(
      new TessellationPass(Programs{std::move(*classify), std::move(*dispatch), std::move(*search), std::move(*decide),
                                    std::move(*layout), std::move(*emit)}));
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
        record.work[0] = {partTriangles, triangles};
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
  for (const gl::ShaderProgram* program :
       {&programs_.classify, &programs_.search, &programs_.decide, &programs_.emit}) {
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
  for (const gl::ShaderProgram* program :
       {&programs_.classify, &programs_.dispatch, &programs_.search, &programs_.decide, &programs_.emit}) {
    program->use();
    program->set("firstRun", static_cast<unsigned>(part.firstRun));
    program->set("runCount", static_cast<unsigned>(part.runCount));
  }
  programs_.layout.use();
  programs_.layout.set("firstRun", static_cast<unsigned>(part.firstRun));
  programs_.layout.set("runCount", static_cast<unsigned>(part.runCount));
  programs_.layout.set("partsLeft", static_cast<unsigned>(frame.plan.mirrors.size() - part.planIndex));

  const int maxLevel = frame.settings.tessellation.maxLevel;
  for (int round = 0; round <= maxLevel; ++round) {
    const int parity = round % 2;
    // Working lists ping-pong: round 0 reads the meshes and writes list 0, round r reads list
    // (r − 1) % 2 and writes the other.
    if (round > 0)
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_WORKING_BINDING, buffers.working((round + 1) % 2));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_NEXT_WORKING_BINDING, buffers.working(round % 2));
    if (round < maxLevel) {
      dispatchRound(frame, programs_.classify, part, round, Work::Triangles);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      programs_.dispatch.use();
      programs_.dispatch.set("fromMesh", round == 0 ? 1 : 0);
      gl.DispatchCompute(groupsFor(part.runCount), 1, 1);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
      dispatchRound(frame, programs_.search, part, round, Work::Searches);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      dispatchRound(frame, programs_.decide, part, round, Work::Triangles);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    programs_.layout.use();
    programs_.layout.set("round", static_cast<unsigned>(round));
    programs_.layout.set("parity", static_cast<unsigned>(parity));
    programs_.layout.set("lastRound", round == maxLevel ? 1 : 0);
    gl.DispatchCompute(1, 1, 1);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    dispatchRound(frame, programs_.emit, part, round, Work::Triangles);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  }
}

void TessellationPass::dispatchRound(const FrameContext& frame, const gl::ShaderProgram& program, const PartRuns& part,
                                     int round, Work work) const {
  const gl::GlApi& gl = frame.gl;
  const TessellationBuffers& buffers = frame.reflections.tessellation();
  program.use();
  program.set("fromMesh", round == 0 ? 1 : 0);
  program.set("parity", static_cast<unsigned>(round % 2));
  if (round > 0) {  // one dispatch over the whole part, sized by the last layout
    gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffers.totals());
    gl.DispatchComputeIndirect(
        static_cast<GLintptr>(work == Work::Triangles ? partGroupsOffset(round % 2) : kPartSearchGroupsOffset));
    return;
  }
  // Round 0 reads each run's own mesh: a dispatch per run, over its triangles (known here) or its
  // searches (counted on the GPU).
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffers.runs());
  const std::vector<TessellatedRun>& runs = buffers.frameRuns();
  for (std::size_t i = part.firstRun; i < part.firstRun + part.runCount; ++i) {
    const TessellatedRun& run = runs[i];
    if (!run.rounds) continue;
    program.set("runIndex", static_cast<unsigned>(i));
    const std::size_t mesh = frame.scene.objects[run.object->object].mesh;
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_MESH_VERTICES_BINDING, frame.meshes.vertexBuffer(mesh));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TESSELLATION_MESH_INDICES_BINDING, frame.meshes.indexBuffer(mesh));
    frame.setReflectedObject(program, *run.object);
    if (work == Work::Triangles) gl.DispatchCompute(groupsFor(run.object->triangleCount), 1, 1);
    else gl.DispatchComputeIndirect(static_cast<GLintptr>(i * sizeof(gpu::TessellationRun) + kRunSearchGroupsOffset));
  }
}

}  // namespace specula::passes
