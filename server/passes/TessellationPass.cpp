#include "passes/TessellationPass.h"

#include "passes/SearchPass.h"

namespace specula::passes {

namespace {
constexpr GLuint kGroupSize = 64;  // local_size_x of the tessellation kernels
// Storage-buffer bindings of shaders/tessellation.
constexpr GLuint kMeshVerticesBinding = 0, kStatisticsBinding = 2, kWorkingBinding = 3, kSplitsBinding = 4,
                 kCountersBinding = 5, kMeshIndicesBinding = 6, kRequestsBinding = 7, kRequestCountsBinding = 8,
                 kFinishedBinding = 9, kNextWorkingBinding = 10;

GLuint groupsFor(std::size_t invocations) { return static_cast<GLuint>((invocations + kGroupSize - 1) / kGroupSize); }
}  // namespace

Result<std::unique_ptr<TessellationPass>> TessellationPass::create(const gl::GlApi& gl) {
  const auto build = [&](std::initializer_list<std::string_view> files) { return gl::ShaderProgram::build(gl, files); };
  auto classify = build({"tessellation/tessellation-classify.comp"});
  if (!classify) return Error{classify.error()};
  auto dispatch = build({"tessellation/tessellation-dispatch.comp"});
  if (!dispatch) return Error{dispatch.error()};
  auto search = build({"tessellation/tessellation-search.comp"});
  if (!search) return Error{search.error()};
  auto decide = build({"tessellation/tessellation-decide.comp"});
  if (!decide) return Error{decide.error()};
  auto emit = build({"tessellation/tessellation-emit.comp"});
  if (!emit) return Error{emit.error()};
  return std::unique_ptr<TessellationPass>(
      new TessellationPass(Programs{std::move(*classify), std::move(*dispatch), std::move(*search), std::move(*decide), std::move(*emit)}));
}

void TessellationPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  buffers.beginFrame();
  const TessellationSettings& settings = frame.settings.tessellation;
  for (const gl::ShaderProgram* program : {&programs_.classify, &programs_.search, &programs_.decide}) {
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
  programs_.classify.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kStatisticsBinding, buffers.midpointStatistics());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, buffers.counters());
  for (std::size_t part = 0; part < frame.plan.mirrors.size(); ++part) {
    const PlannedMirror& planned = frame.plan.mirrors[part];
    if (planned.method != PartMethod::VirtualObjects) continue;
    const MirrorSlots* mirror = planned.slots;
    for (const gl::ShaderProgram* program : {&programs_.classify, &programs_.search}) {
      program->use();
      setSearchMirror(*program, frame, *mirror);
    }
    programs_.classify.use();
    programs_.classify.set("mirrorRect", frame.reflections.coveredFramePixels(mirror->layer));
    const math::Bounds& bounds = frame.worldBounds[mirror->mirrorObject];
    programs_.classify.set("mirrorSphere", glm::vec4(bounds.center(), bounds.radius()));
    programs_.classify.set("everyCornerReflected", mirror->kind == scene::SurfaceKind::Convex ? 0 : 1);
    // Each part may take an even share of what is left of the finished list, so one part's
    // full tessellation cannot leave the next none.
    const std::size_t partsLeft = frame.plan.mirrors.size() - part;
    tessellateMirror(frame, planned,
                     buffers.finishedCount() + (TessellationBuffers::kMaxTriangles - buffers.finishedCount()) / partsLeft);
  }
  buffers.finishStatistics();
}

void TessellationPass::tessellateMirror(const FrameContext& frame, const PlannedMirror& mirror, std::size_t finishedBudget) {
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  TessellationStatistics& statistics = buffers.statistics();
  const TessellationSettings& settings = frame.settings.tessellation;

  // Every reflected object of the mirror goes through the rounds together, each in its own run of
  // the working list, so a round costs one readback whatever the number of objects.
  const auto drawFromMesh = [&](const ReflectionSlotRange* range) {
    buffers.ranges().push_back({mirror.slots, range, 0, static_cast<GLsizei>(range->triangleCount), true});
    statistics.finishedTriangles += range->triangleCount;
  };
  std::vector<ObjectRun> runs;
  std::size_t total = 0, everyTriangle = 0;
  for (std::size_t i = 0; i < mirror.reflected.size(); ++i) {
    const ReflectionSlotRange* range = mirror.reflected[i];
    everyTriangle += range->triangleCount;
    if (range->triangleCount == 0) continue;
    if (!mirror.tessellated[i]) {  // the plan predicts no split: no round for it
      statistics.inputTriangles += range->triangleCount;
      ++statistics.predictedUnsplitObjects;
      drawFromMesh(range);
      continue;
    }
    runs.push_back({range, total, range->triangleCount});
    total += range->triangleCount;
  }
  if (runs.empty()) return;
  statistics.inputTriangles += static_cast<std::uint32_t>(total);
  // Sized for every reflected triangle when that fits (the working lists too, below), so which
  // objects the plan leaves unsplit this frame does not grow the buffers from one frame to the next.
  const std::size_t sizedFor = std::min(everyTriangle, TessellationBuffers::kMaxTriangles);
  const std::size_t sized = std::max(total, sizedFor);
  if (!buffers.reserveSplits(sized) || !buffers.reserveRequests(sized, mirror.reflected.size())) {
    statistics.capped = true;
    for (const ObjectRun& run : runs) drawFromMesh(run.range);
    return;
  }

  // Round 0 decides on the meshes themselves. Objects nothing splits are drawn from their meshes;
  // the others' rounds begin there too, reading corners from the mesh and its search slots.
  buffers.resetCounters(runs.size());
  decideRound(frame, runs, true);
  std::vector<TessellationBuffers::RoundCounts> counts = buffers.readCounters(runs.size());
  if (statistics.trianglesPerRound.empty()) statistics.trianglesPerRound.push_back(0);
  statistics.trianglesPerRound[0] += static_cast<std::uint32_t>(total);
  std::vector<ObjectRun> splitting;
  std::vector<TessellationBuffers::RoundCounts> splittingCounts;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (counts[i].children == 0) {
      drawFromMesh(runs[i].range);
      continue;
    }
    splitting.push_back(runs[i]);
    splittingCounts.push_back(counts[i]);
  }
  runs = std::move(splitting);
  counts = std::move(splittingCounts);

  // Working lists ping-pong: round 0 reads the meshes and writes list 0, round r reads list
  // (r − 1) % 2 and writes the other.
  for (int round = 0; !runs.empty(); ++round) {
    const bool fromMesh = round == 0;
    const int from = (round + 1) % 2, to = round % 2;
    total = 0;
    for (const ObjectRun& run : runs) total += run.triangles;
    bool last = round >= settings.maxLevel;
    if (round > 0) {
      if (statistics.trianglesPerRound.size() <= static_cast<std::size_t>(round)) statistics.trianglesPerRound.push_back(0);
      statistics.trianglesPerRound[static_cast<std::size_t>(round)] += static_cast<std::uint32_t>(total);
      last = last || !buffers.reserveSplits(total) || !buffers.reserveRequests(total, runs.size());
      counts.assign(runs.size(), {});
      if (!last) {
        buffers.resetCounters(runs.size());
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(from));
        decideRound(frame, runs, false);
        counts = buffers.readCounters(runs.size());
      }
    }
    std::size_t children = 0, unsplit = 0;
    for (const auto& count : counts) {
      children += count.children;
      unsplit += count.unsplit;
    }
    // Past the cap or this part's share of the finished list: the working triangles finish here
    // (they fit the share, since the last round's check counted them as children).
    if (!last && children > 0 &&
        (buffers.finishedCount() + unsplit + children > finishedBudget ||
         !buffers.reserveWorking(to, std::max(children, sizedFor))))
      last = true;
    if (last && round < settings.maxLevel) statistics.capped = true;
    if (last) {
      for (std::size_t i = 0; i < runs.size(); ++i) counts[i] = {0, static_cast<std::uint32_t>(runs[i].triangles)};
      unsplit = total;
    }
    if (!buffers.reserveFinished(unsplit)) {
      // The finished list is full (a round-0 mesh larger than the share): these objects are drawn
      // whole from their meshes, over what earlier rounds finished of them. Per-pixel exact hits
      // make the overlap draw the same pixels twice, so only coverage is coarser, where dropping
      // the round left holes.
      statistics.capped = true;
      for (const ObjectRun& run : runs) drawFromMesh(run.range);
      return;
    }

    // Emission: each object's unsplit triangles go to its range of the finished list, its children
    // to its run of the next working list; the counters, zeroed again, hand out places.
    buffers.resetCounters(runs.size());
    programs_.emit.use();
    programs_.emit.set("fromMesh", fromMesh ? 1 : 0);
    programs_.emit.set("finishAll", last ? 1 : 0);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
    if (!fromMesh) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(from));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kFinishedBinding, buffers.finished());
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kNextWorkingBinding, buffers.working(to));
    std::vector<ObjectRun> next;
    std::size_t nextTotal = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      setRun(frame, programs_.emit, runs, i, fromMesh);
      programs_.emit.set("finishedBase", static_cast<unsigned>(buffers.finishedCount()));
      programs_.emit.set("childrenBase", static_cast<unsigned>(nextTotal));
      gl.DispatchCompute(groupsFor(runs[i].triangles), 1, 1);
      if (counts[i].unsplit > 0) {
        buffers.ranges().push_back({mirror.slots, runs[i].range, static_cast<GLint>(buffers.finishedCount()),
                                    static_cast<GLsizei>(counts[i].unsplit), false});
        buffers.addFinished(counts[i].unsplit);
      }
      if (counts[i].children == 0) continue;
      next.push_back({runs[i].range, nextTotal, counts[i].children});
      nextTotal += counts[i].children;
    }
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    runs = std::move(next);
  }
}

void TessellationPass::decideRound(const FrameContext& frame, const std::vector<ObjectRun>& runs, bool fromMesh) const {
  const gl::GlApi& gl = frame.gl;
  const TessellationBuffers& buffers = frame.reflections.tessellation();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kRequestsBinding, buffers.requests());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kRequestCountsBinding, buffers.requestCounts());

  programs_.classify.use();
  programs_.classify.set("fromMesh", fromMesh ? 1 : 0);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    setRun(frame, programs_.classify, runs, i, fromMesh);
    gl.DispatchCompute(groupsFor(runs[i].triangles), 1, 1);
  }
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  programs_.dispatch.use();
  programs_.dispatch.set("runCount", static_cast<unsigned>(runs.size()));
  gl.DispatchCompute(groupsFor(runs.size()), 1, 1);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  programs_.search.use();
  programs_.search.set("fromMesh", fromMesh ? 1 : 0);
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffers.requestCounts());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    setRun(frame, programs_.search, runs, i, fromMesh);
    // The run's work-group count sits after its request count.
    gl.DispatchComputeIndirect(static_cast<GLintptr>(i * TessellationBuffers::kRunRequestBytes + sizeof(std::uint32_t)));
  }
  gl.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  programs_.decide.use();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    setRun(frame, programs_.decide, runs, i, fromMesh);
    gl.DispatchCompute(groupsFor(runs[i].triangles), 1, 1);
  }
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void TessellationPass::setRun(const FrameContext& frame, const gl::ShaderProgram& program, const std::vector<ObjectRun>& runs,
                              std::size_t i, bool fromMesh) const {
  program.set("firstTriangle", static_cast<unsigned>(runs[i].first));
  program.set("triangleCount", static_cast<unsigned>(runs[i].triangles));
  program.set("runIndex", static_cast<unsigned>(i));
  if (!fromMesh) return;
  const std::size_t mesh = frame.scene.objects[runs[i].range->object].mesh;
  frame.gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshVerticesBinding, frame.meshes.vertexBuffer(mesh));
  frame.gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshIndicesBinding, frame.meshes.indexBuffer(mesh));
  frame.setReflectedObject(program, *runs[i].range);
}

}  // namespace specula::passes
