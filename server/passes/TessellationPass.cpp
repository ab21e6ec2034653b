#include "passes/TessellationPass.h"

#include <array>

#include "passes/SearchPass.h"

namespace specula::passes {

namespace {
constexpr std::array<std::string_view, 2> kReads{"mirror-gbuffer", "reflected-vertices"};
constexpr std::array<std::string_view, 1> kWrites{"tessellated-triangles"};
constexpr GLuint kGroupSize = 64;  // local_size_x of tessellation-split.comp
// Storage-buffer bindings of shaders/tessellation.
constexpr GLuint kMeshVerticesBinding = 0, kStatisticsBinding = 2, kWorkingBinding = 3, kSplitsBinding = 4,
                 kCountersBinding = 5, kMeshIndicesBinding = 6;
}  // namespace

Result<std::unique_ptr<TessellationPass>> TessellationPass::create(const gl::GlApi& gl) {
  auto seed = gl::ShaderProgram::build(gl, {"tessellation/tessellation-seed.vert"});
  if (!seed) return Error{seed.error()};
  auto split = gl::ShaderProgram::build(gl, {"tessellation/tessellation-split.comp"});
  if (!split) return Error{split.error()};
  auto emit = gl::ShaderProgram::build(gl, {"tessellation/tessellation-emit.vert", "tessellation/tessellation-emit.geom"});
  if (!emit) return Error{emit.error()};
  return std::unique_ptr<TessellationPass>(
      new TessellationPass(gl, std::move(seed.value()), std::move(split.value()), std::move(emit.value())));
}

std::span<const std::string_view> TessellationPass::reads() const { return kReads; }
std::span<const std::string_view> TessellationPass::writes() const { return kWrites; }

void TessellationPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  buffers.beginFrame();
  const TessellationSettings& settings = frame.settings.tessellation;
  split_.use();
  setSearchUniforms(split_, frame);
  split_.set("crackFree", settings.mode == TessellationMode::CrackFree ? 1 : 0);
  split_.set("pixelMetric", settings.metric == TessellationMetric::Pixels ? 1 : 0);
  split_.set("threshold", settings.threshold);
  split_.set("gbufferWorldToClip", frame.gbufferWorldToClip());
  split_.set("frameWorldToClip", frame.view.worldToClip());
  split_.set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kStatisticsBinding, buffers.midpointStatistics());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, buffers.counters());
  gl.Enable(GL_RASTERIZER_DISCARD);
  for (const MirrorSlots* mirror : frame.plan.mirrors) {
    split_.use();
    setSearchMirror(split_, frame, *mirror);
    split_.set("mirrorRect", frame.reflections.coveredFramePixels(mirror->layer));
    const math::Bounds& bounds = frame.worldBounds[mirror->mirrorObject];
    split_.set("mirrorSphere", glm::vec4(bounds.center(), bounds.radius()));
    tessellateMirror(frame, *mirror);
  }
  gl.Disable(GL_RASTERIZER_DISCARD);
  gl.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  buffers.finishStatistics();
}

void TessellationPass::tessellateMirror(const FrameContext& frame, const MirrorSlots& mirror) {
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  TessellationStatistics& statistics = buffers.statistics();
  const TessellationSettings& settings = frame.settings.tessellation;

  // Every reflected object of the mirror goes through the rounds together, each in its own run of
  // the working list, so a round costs one readback whatever the number of objects.
  struct ObjectRun {
    const ReflectionSlotRange* range;
    std::size_t first = 0, triangles = 0;
  };
  std::vector<ObjectRun> runs;
  std::size_t total = 0;
  for (const ReflectionSlotRange& range : mirror.reflected) {
    const std::size_t triangles = frame.scene.meshes[frame.scene.objects[range.object].mesh].triangleCount();
    if (triangles == 0) continue;
    runs.push_back({&range, total, triangles});
    total += triangles;
  }
  if (runs.empty()) return;
  statistics.inputTriangles += static_cast<std::uint32_t>(total);
  const auto drawFromMesh = [&](const ObjectRun& run) {
    buffers.ranges().push_back({mirror.mirrorObject, run.range, 0, static_cast<GLsizei>(run.triangles), true});
    statistics.finishedTriangles += static_cast<std::uint32_t>(run.triangles);
  };
  if (!buffers.reserveSplits(total) || !buffers.reserveWorking(0, total)) {
    statistics.capped = true;
    for (const ObjectRun& run : runs) drawFromMesh(run);
    return;
  }

  // Round 0 decides on the meshes themselves. Objects nothing splits are drawn from their meshes;
  // only the others are copied, with their corners' search results, into the working list.
  split_.use();
  split_.set("fromMesh", 1);
  buffers.resetCounters(runs.size());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::size_t mesh = frame.scene.objects[runs[i].range->object].mesh;
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshVerticesBinding, frame.meshes.vertexBuffer(mesh));
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshIndicesBinding, frame.meshes.indexBuffer(mesh));
    frame.setReflectedObject(split_, *runs[i].range);
    dispatchSplit(frame, runs[i].first, runs[i].triangles, i);
  }
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  std::vector<TessellationBuffers::RoundCounts> counts = buffers.readCounters(runs.size());
  split_.set("fromMesh", 0);
  if (statistics.trianglesPerRound.empty()) statistics.trianglesPerRound.push_back(0);
  statistics.trianglesPerRound[0] += static_cast<std::uint32_t>(total);

  std::vector<ObjectRun> splitting;
  std::vector<TessellationBuffers::RoundCounts> splittingCounts;
  seed_.use();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (counts[i].children == 0) {
      drawFromMesh(runs[i]);
      continue;
    }
    splitting.push_back(runs[i]);
    splittingCounts.push_back(counts[i]);
    frame.setReflectedObject(seed_, *runs[i].range);
    gl.BindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers.working(0),
                       static_cast<GLintptr>(runs[i].first * TessellationBuffers::kTriangleBytes),
                       static_cast<GLsizeiptr>(runs[i].triangles * TessellationBuffers::kTriangleBytes));
    gl.BeginTransformFeedback(GL_TRIANGLES);
    frame.meshes.draw(frame.scene.objects[runs[i].range->object].mesh);
    gl.EndTransformFeedback();
  }
  runs = std::move(splitting);
  counts = std::move(splittingCounts);

  int list = 0;
  for (int round = 0; !runs.empty(); ++round) {
    total = 0;
    for (const ObjectRun& run : runs) total += run.triangles;
    bool last = round >= settings.maxLevel;
    if (round > 0) {
      if (statistics.trianglesPerRound.size() <= static_cast<std::size_t>(round)) statistics.trianglesPerRound.push_back(0);
      statistics.trianglesPerRound[static_cast<std::size_t>(round)] += static_cast<std::uint32_t>(total);
      last = last || !buffers.reserveSplits(runs.back().first + runs.back().triangles);
      counts.assign(runs.size(), {});
      if (!last) {
        split_.use();
        buffers.resetCounters(runs.size());
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(list));
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
        for (std::size_t i = 0; i < runs.size(); ++i) dispatchSplit(frame, runs[i].first, runs[i].triangles, i);
        gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        counts = buffers.readCounters(runs.size());
      }
    }
    std::size_t children = 0, unsplit = 0;
    for (const auto& count : counts) children += count.children;
    if (!last && children > 0 && !buffers.reserveWorking(1 - list, children)) last = true;  // past the cap: finish here
    if (last && round < settings.maxLevel) statistics.capped = true;
    if (last)
      for (std::size_t i = 0; i < runs.size(); ++i) counts[i] = {0, static_cast<std::uint32_t>(runs[i].triangles)};
    for (const auto& count : counts) unsplit += count.unsplit;
    if (!buffers.reserveFinished(unsplit)) {
      statistics.capped = true;
      return;
    }
    std::vector<ObjectRun> next;
    std::size_t nextTotal = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (counts[i].unsplit > 0) {
        emit(frame, list, runs[i].first, runs[i].triangles, last, false, buffers.finished(), buffers.finishedCount(), counts[i].unsplit);
        buffers.ranges().push_back({mirror.mirrorObject, runs[i].range, static_cast<GLint>(buffers.finishedCount()),
                                    static_cast<GLsizei>(counts[i].unsplit), false});
        buffers.addFinished(counts[i].unsplit);
      }
      if (counts[i].children == 0) continue;
      emit(frame, list, runs[i].first, runs[i].triangles, false, true, buffers.working(1 - list), nextTotal, counts[i].children);
      next.push_back({runs[i].range, nextTotal, counts[i].children});
      nextTotal += counts[i].children;
    }
    runs = std::move(next);
    list = 1 - list;
  }
}

void TessellationPass::dispatchSplit(const FrameContext& frame, std::size_t firstTriangle, std::size_t triangles,
                                     std::size_t counterIndex) const {
  split_.set("firstTriangle", static_cast<unsigned>(firstTriangle));
  split_.set("triangleCount", static_cast<unsigned>(triangles));
  split_.set("counterIndex", static_cast<unsigned>(counterIndex));
  frame.gl.DispatchCompute(static_cast<GLuint>((triangles + kGroupSize - 1) / kGroupSize), 1, 1);
}

void TessellationPass::emit(const FrameContext& frame, int from, std::size_t firstTriangle, std::size_t triangles,
                            bool finishAll, bool emitChildren, GLuint target, std::size_t targetTriangle,
                            std::size_t count) const {
  if (count == 0) return;
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  emit_.use();
  emit_.set("finishAll", finishAll ? 1 : 0);
  emit_.set("emitChildren", emitChildren ? 1 : 0);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(from));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
  gl.BindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, target,
                     static_cast<GLintptr>(targetTriangle * TessellationBuffers::kTriangleBytes),
                     static_cast<GLsizeiptr>(count * TessellationBuffers::kTriangleBytes));
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.BeginTransformFeedback(GL_TRIANGLES);
  gl.DrawArrays(GL_TRIANGLES, static_cast<GLint>(3 * firstTriangle), static_cast<GLsizei>(3 * triangles));
  gl.EndTransformFeedback();
  gl.BindVertexArray(0);
}

}  // namespace specula::passes
