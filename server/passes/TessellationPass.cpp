#include "passes/TessellationPass.h"

#include <array>

#include "math/Transform.h"
#include "passes/SearchPass.h"

namespace specula::passes {

namespace {
constexpr std::array<std::string_view, 2> kReads{"mirror-gbuffer", "reflected-vertices"};
constexpr std::array<std::string_view, 1> kWrites{"tessellated-triangles"};
constexpr GLuint kGroupSize = 64;  // local_size_x of tessellation-split.comp
// Storage-buffer bindings of shaders/tessellation.
constexpr GLuint kWorkingBinding = 3, kSplitsBinding = 4, kCountersBinding = 5, kStatisticsBinding = 2;
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
  split_.set("gbufferWorldToClip", frame.view.worldToClip(glm::vec2(frame.reflections.size()) /
                                                          glm::vec2(frame.target.width(), frame.target.height())));
  split_.set("frameWorldToClip", frame.view.worldToClip());
  split_.set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kStatisticsBinding, buffers.midpointStatistics());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, buffers.counters());
  gl.Enable(GL_RASTERIZER_DISCARD);
  for (const MirrorSlots* mirror : frame.plan.mirrors) {
    split_.use();
    setSearchMirror(split_, frame, *mirror);
    // The G-buffer is the frame widened by the margin at one texel per pixel.
    const TexelRect& covered = frame.reflections.coveredRect(mirror->layer);
    const glm::vec2 margin(frame.reflections.margin());
    split_.set("mirrorRect", glm::vec4(glm::vec2(covered.low) - margin, glm::vec2(covered.high) - margin));
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
  if (!buffers.reserveWorking(0, total)) {
    statistics.capped = true;
    return;
  }
  statistics.inputTriangles += static_cast<std::uint32_t>(total);

  // Round 0's working list: the objects' triangles with their corners' search results.
  seed_.use();
  for (const ObjectRun& run : runs) {
    const glm::mat4& objectToWorld = frame.pose.objectToWorld[run.range->object];
    seed_.set("objectToWorld", objectToWorld);
    seed_.set("normalToWorld", math::normalMatrix(objectToWorld));
    seed_.set("firstSlot", static_cast<unsigned>(run.range->firstSlot));
    gl.BindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers.working(0),
                       static_cast<GLintptr>(run.first * TessellationBuffers::kTriangleBytes),
                       static_cast<GLsizeiptr>(run.triangles * TessellationBuffers::kTriangleBytes));
    gl.BeginTransformFeedback(GL_TRIANGLES);
    frame.meshes.draw(frame.scene.objects[run.range->object].mesh);
    gl.EndTransformFeedback();
  }

  int list = 0;
  for (int round = 0; !runs.empty(); ++round) {
    if (statistics.trianglesPerRound.size() <= static_cast<std::size_t>(round)) statistics.trianglesPerRound.push_back(0);
    statistics.trianglesPerRound[static_cast<std::size_t>(round)] += static_cast<std::uint32_t>(total);
    bool last = round >= settings.maxLevel || !buffers.reserveSplits(total);
    std::vector<TessellationBuffers::RoundCounts> counts(runs.size());
    if (!last) {
      split_.use();
      buffers.resetCounters(runs.size());
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(list));
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
      for (std::size_t i = 0; i < runs.size(); ++i) {
        split_.set("firstTriangle", static_cast<unsigned>(runs[i].first));
        split_.set("triangleCount", static_cast<unsigned>(runs[i].triangles));
        split_.set("counterIndex", static_cast<unsigned>(i));
        gl.DispatchCompute(static_cast<GLuint>((runs[i].triangles + kGroupSize - 1) / kGroupSize), 1, 1);
      }
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      counts = buffers.readCounters(runs.size());
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
    // One draw per list for all objects: the geometry shader's output keeps input order, so each
    // object's triangles stay together, where its counts say.
    emit(frame, list, total, last, false, buffers.finished(), buffers.finishedCount(), unsplit);
    if (children > 0) emit(frame, list, total, false, true, buffers.working(1 - list), 0, children);
    std::vector<ObjectRun> next;
    std::size_t nextTotal = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (counts[i].unsplit > 0) {
        buffers.ranges().push_back({mirror.mirrorObject, runs[i].range->object, static_cast<GLint>(buffers.finishedCount()),
                                    static_cast<GLsizei>(counts[i].unsplit)});
        buffers.addFinished(counts[i].unsplit);
      }
      if (counts[i].children == 0) continue;
      next.push_back({runs[i].range, nextTotal, counts[i].children});
      nextTotal += counts[i].children;
    }
    runs = std::move(next);
    total = nextTotal;
    list = 1 - list;
  }
}

void TessellationPass::emit(const FrameContext& frame, int from, std::size_t triangles, bool finishAll, bool emitChildren,
                            GLuint target, std::size_t targetTriangle, std::size_t count) const {
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
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles));
  gl.EndTransformFeedback();
  gl.BindVertexArray(0);
}

}  // namespace specula::passes
