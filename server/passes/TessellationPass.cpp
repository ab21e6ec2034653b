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
    for (const ReflectionSlotRange& range : mirror->reflected) tessellateObject(frame, *mirror, range);
  }
  gl.Disable(GL_RASTERIZER_DISCARD);
  gl.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  buffers.finishStatistics();
}

void TessellationPass::tessellateObject(const FrameContext& frame, const MirrorSlots& mirror, const ReflectionSlotRange& range) {
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  TessellationStatistics& statistics = buffers.statistics();
  const scene::SceneObject& object = frame.scene.objects[range.object];
  std::size_t triangles = frame.scene.meshes[object.mesh].triangleCount();
  if (triangles == 0) return;
  if (!buffers.reserveWorking(0, triangles)) {
    statistics.capped = true;
    return;
  }
  statistics.inputTriangles += static_cast<std::uint32_t>(triangles);

  // Round 0's working list: the object's triangles with their corners' search results.
  seed_.use();
  const glm::mat4& objectToWorld = frame.pose.objectToWorld[range.object];
  seed_.set("objectToWorld", objectToWorld);
  seed_.set("normalToWorld", math::normalMatrix(objectToWorld));
  seed_.set("firstSlot", static_cast<unsigned>(range.firstSlot));
  gl.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers.working(0));
  gl.BeginTransformFeedback(GL_TRIANGLES);
  frame.meshes.draw(object.mesh);
  gl.EndTransformFeedback();

  const TessellationSettings& settings = frame.settings.tessellation;
  const std::size_t firstFinished = buffers.finishedCount();
  int list = 0;
  for (int round = 0;; ++round) {
    if (statistics.trianglesPerRound.size() <= static_cast<std::size_t>(round)) statistics.trianglesPerRound.push_back(0);
    statistics.trianglesPerRound[static_cast<std::size_t>(round)] += static_cast<std::uint32_t>(triangles);
    bool last = round >= settings.maxLevel;
    std::uint32_t children = 0, unsplit = static_cast<std::uint32_t>(triangles);
    if (!last && buffers.reserveSplits(triangles)) {
      split_.use();
      split_.set("triangleCount", static_cast<unsigned>(triangles));
      buffers.resetCounters();
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(list));
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
      gl.DispatchCompute(static_cast<GLuint>((triangles + kGroupSize - 1) / kGroupSize), 1, 1);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      std::tie(children, unsplit) = buffers.readCounters();
      if (children > 0 && !buffers.reserveWorking(1 - list, children)) {  // past the cap: finish here
        statistics.capped = true;
        last = true;
      }
    } else if (!last) {
      statistics.capped = true;
      last = true;
    }
    if (last) {
      children = 0;
      unsplit = static_cast<std::uint32_t>(triangles);
    }
    if (!buffers.reserveFinished(unsplit)) {
      statistics.capped = true;
      break;
    }
    emit(frame, list, triangles, last, false, buffers.finished(), buffers.finishedCount(), unsplit);
    buffers.addFinished(unsplit);
    if (children == 0) break;
    emit(frame, list, triangles, false, true, buffers.working(1 - list), 0, children);
    list = 1 - list;
    triangles = children;
  }
  buffers.ranges().push_back({mirror.mirrorObject, range.object, static_cast<GLint>(firstFinished),
                              static_cast<GLsizei>(buffers.finishedCount() - firstFinished)});
}

void TessellationPass::emit(const FrameContext& frame, int from, std::size_t triangles, bool finishAll, bool emitChildren,
                            GLuint target, std::size_t firstTriangle, std::size_t count) const {
  if (count == 0) return;
  const gl::GlApi& gl = frame.gl;
  TessellationBuffers& buffers = frame.reflections.tessellation();
  emit_.use();
  emit_.set("finishAll", finishAll ? 1 : 0);
  emit_.set("emitChildren", emitChildren ? 1 : 0);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkingBinding, buffers.working(from));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplitsBinding, buffers.splits());
  gl.BindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, target,
                     static_cast<GLintptr>(firstTriangle * TessellationBuffers::kTriangleBytes),
                     static_cast<GLsizeiptr>(count * TessellationBuffers::kTriangleBytes));
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.BeginTransformFeedback(GL_TRIANGLES);
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangles));
  gl.EndTransformFeedback();
  gl.BindVertexArray(0);
}

}  // namespace specula::passes
