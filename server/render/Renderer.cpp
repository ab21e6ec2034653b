#include "render/Renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>

#include "gl/GlErrors.h"
#include "gl/GlObject.h"
#include "gl/RenderTarget.h"
#include "math/Camera.h"
#include "math/SamplePattern.h"
#include "passes/EnvironmentMapPass.h"
#include "passes/FramePlan.h"
#include "passes/GBufferPyramidPass.h"
#include "passes/MirrorGBufferPass.h"
#include "passes/ExplosionMapPass.h"
#include "passes/RayHierarchyPass.h"
#include "passes/ScenePass.h"
#include "passes/SearchPass.h"
#include "passes/TessellationPass.h"
#include "passes/VirtualObjectsPass.h"

namespace specula::render {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Nearest clip distance as a share of the far one when the eye is inside the scene's bounds:
// keeps 24-bit depth precise to ~1e-4 of the far distance.
constexpr float kNearFarRatio = 1.0f / 2000.0f;

// `kept`, when given, keeps a typed pointer to the pass for what the renderer reads back from it.
template <class P>
Status addPass(Renderer::PassTable& passes, Result<std::unique_ptr<P>> pass, P** kept = nullptr) {
  if (!pass) return Error{pass.error()};
  if (kept) *kept = pass->get();
  const auto index = static_cast<std::size_t>((*pass)->id());
  passes[index] = std::move(pass.value());
  return {};
}

// Mesa's software rasterizers (llvmpipe, softpipe, swrast) by their GL_RENDERER string.
bool isCpuRasterizer(const std::string& renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast"})
    if (renderer.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace

Renderer::Renderer(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene, passes::ReflectionSlots slots,
                   passes::GpuDeformation deformation)
    : context_(context),
      scene_(std::move(scene)),
      meshes_(context.api(), scene_->meshes),
      deformation_(std::move(deformation)),
      textures_(context.api(), scene_->textures),
      slots_(std::move(slots)),
      reflections_(context.api(), *scene_, slots_, meshes_, deformation_),
      readback_(context.api()),
      cpuRasterizer_(isCpuRasterizer(context.info().renderer)) {
  for (const scene::Mesh& mesh : scene_->meshes) {
    math::Bounds bounds;
    for (const scene::Vertex& v : mesh.vertices) bounds.add(v.position);
    meshBounds_.push_back(bounds);
  }
}

Renderer::~Renderer() = default;

Result<passes::PatchTessellationMeasure> Renderer::measurePatchTessellation(const scene::ScenePose& pose,
                                                                            const RenderedFrame& frame) {
  if (!patchProbe_) {
    auto probe = passes::PatchTessellationProbe::create(context_.api());
    if (!probe) return Error{probe.error()};
    patchProbe_.emplace(std::move(probe.value()));
  }
  return patchProbe_->measure(*scene_, pose, meshes_, frame.view.worldToClip(), {frame.width, frame.height});
}

Result<std::unique_ptr<Renderer>> Renderer::create(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene) {
  const gl::GlApi& gl = context.api();
  passes::ReflectionSlots slots = passes::ReflectionSlots::forScene(*scene);
  // Before any buffer exists: past these limits the search would read and write out of range.
  if (auto problem = passes::searchLimitProblem(gl, *scene, slots)) return Error{*problem};
  Result<passes::GpuDeformation> deformation = passes::GpuDeformation::create(gl, *scene);
  if (!deformation) return Error{deformation.error()};
  std::unique_ptr<Renderer> renderer(
      new Renderer(context, std::move(scene), std::move(slots), std::move(deformation.value())));
  for (Status status : {addPass(renderer->passes_, passes::ScenePass::create(gl)),
                        addPass(renderer->passes_, passes::MirrorGBufferPass::create(gl)),
                        addPass(renderer->passes_, passes::GBufferPyramidPass::create(gl)),
                        addPass(renderer->passes_, passes::RayHierarchyPass::create(gl)),
                        addPass(renderer->passes_, passes::ExplosionMapPass::create(gl)),
                        addPass(renderer->passes_, passes::SearchPass::create(gl)),
                        addPass(renderer->passes_, passes::TessellationPass::create(gl)),
                        addPass(renderer->passes_, passes::VirtualObjectsPass::create(gl), &renderer->virtualObjects_),
                        addPass(renderer->passes_, passes::EnvironmentMapPass::create(gl))})
    if (!status) return Error{status.error()};
  return renderer;
}

passes::FrameView Renderer::frameView(const math::Camera& camera, const std::vector<math::Bounds>& worldBounds,
                                      float aspect) const {
  math::Bounds all;
  for (const math::Bounds& bounds : worldBounds) all.add(bounds);
  passes::FrameView view{math::viewMatrix(camera), camera.fovYDegrees, aspect, 0.1f, 100.0f};
  if (all.empty()) return view;
  const float distance = glm::length(all.center() - camera.eye);
  view.farDistance = (distance + all.radius()) * 1.01f;
  view.nearDistance = std::max(distance - all.radius(), view.farDistance * kNearFarRatio);
  return view;
}

Result<RenderedFrame> Renderer::render(const scene::ScenePose& pose, int width, int height,
                                       const passes::ReflectionSettings& settings, int samples) {
  if (auto problem = math::cameraProblem(pose.camera)) return Error{"cannot render: " + *problem};
  if (auto problem = passes::reflectionSettingsProblem(settings)) return Error{"cannot render: " + *problem};
  if (auto problem = math::sampleCountProblem(samples)) return Error{"cannot render: " + *problem};
  const Clock::time_point start = Clock::now();
  // The planner learns its rates where it chooses (RayCastRule::WhenCheaper), from one-sample frames.
  const bool learning = settings.rayCast == passes::RayCastRule::WhenCheaper &&
                        settings.plan == passes::PlanScope::Needed &&
                        settings.method == passes::ReflectionMethod::Search && samples == 1;
  const passes::MeasuredCosts::FrameRole role = learning ? costs_.nextFrame() : passes::MeasuredCosts::FrameRole{};
  // A frame whose tessellation outgrew its lists is drawn again once they have grown (a few times at
  // most, each growing them by half again up to their cap), so no frame is coarser for it.
  for (;;) {
    bool outgrown = false;
    Result<RenderedFrame> frame = renderOnce(pose, width, height, settings, samples, role, start, outgrown);
    if (!frame || !outgrown) return frame;
  }
}

Result<RenderedFrame> Renderer::renderOnce(const scene::ScenePose& pose, int width, int height,
                                           const passes::ReflectionSettings& settings, int samples,
                                           passes::MeasuredCosts::FrameRole role, Clock::time_point start,
                                           bool& tessellationOutgrown) {
  const gl::GlApi& gl = context_.api();
  if (!target_ || target_->width() != width || target_->height() != height) {
    target_.reset();  // free the old frame before allocating the new one
    auto target = gl::RenderTarget::create(gl, width, height);
    if (!target) return Error{target.error()};
    target_.emplace(std::move(*target));
  }

  std::vector<math::Bounds> worldBounds;
  worldBounds.reserve(scene_->objects.size());
  for (std::size_t i = 0; i < scene_->objects.size(); ++i) {
    const std::uint32_t mesh = scene_->objects[i].mesh;
    const math::Bounds bounds = deformation_.deforms(mesh) ? deformation_.bounds(mesh, pose) : meshBounds_[mesh];
    worldBounds.push_back(bounds.transformed(pose.objectToWorld[i]));
  }
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  passes::FrameView view = frameView(pose.camera, worldBounds, aspect);
  const passes::FramePlan plan =
      passes::planFrame(slots_, pose, worldBounds, {width, height}, settings, costs_.rates(), role.explore);
  if (auto problem = passes::planProblem(plan.passes, plan.needs)) return Error{"cannot render: " + *problem};
  if (!plan.mirrors.empty()) {
    const glm::ivec2 margin(static_cast<int>(std::lround(settings.gbufferMargin * static_cast<float>(width))),
                            static_cast<int>(std::lround(settings.gbufferMargin * static_cast<float>(height))));
    if (Status status = reflections_.prepare(width, height, margin, settings.gbufferScale, plan.gbufferPrecision);
        !status)
      return Error{status.error()};
  }
  const passes::FrameContext frame{gl,   *scene_, pose,     worldBounds, meshes_,     textures_,
                                   view, plan,    settings, *target_,    reflections_};

  // Stage i runs between marks i and i + 1. Per-pass timing (PassTiming::PerPass): GPU timestamps,
  // or on a CPU rasterizer, which runs a pass's draws only when a later command flushes them
  // (timestamps there charged the scene pass's rasterization to whichever pass came last), the
  // wall clock after the pass has finished. PassTiming::FrameOnly names the stages and times the frame.
  const bool timePasses = passTiming_ == PassTiming::PerPass || role.measure;
  std::vector<std::string_view> stages;  // stage i ran between marks i and i + 1
  std::vector<double> wallMarks;
  std::size_t marks = 0;
  const auto mark = [&] {
    if (!timePasses) {
    } else if (cpuRasterizer_) {
      gl.Finish();
      wallMarks.push_back(millisecondsSince(start));
    } else {
      while (stamps_.size() <= marks) stamps_.emplace_back(gl);
      gl.QueryCounter(stamps_[marks].id(), GL_TIMESTAMP);
    }
    ++marks;
  };
  const auto endStage = [&](std::string_view name) {
    stages.push_back(name);
    mark();
  };
  mark();
  if (deformation_.apply(pose, meshes_)) endStage("deform");  // once a frame, before any pass reads a mesh
  // An anti-aliased frame is the plan's passes once per sample point, averaged (SampleAccumulator).
  const std::span<const glm::vec2> points = math::samplePattern(samples);
  if (samples > 1) {
    if (!accumulator_) {
      auto accumulator = SampleAccumulator::create(gl);
      if (!accumulator) return Error{accumulator.error()};
      accumulator_.emplace(std::move(accumulator.value()));
    }
    if (Status status = accumulator_->begin(*target_); !status) return Error{status.error()};
  }
  for (const glm::vec2& point : points) {
    view.jitterClip =
        glm::vec2(2.0f * point.x / static_cast<float>(width), -2.0f * point.y / static_cast<float>(height));
    for (passes::PassId pass : plan.passes) {
      passes_[static_cast<std::size_t>(pass)]->execute(frame);
      endStage(passes::passName(pass));
    }
    if (samples > 1) {
      accumulator_->add(*target_, 1.0f / static_cast<float>(samples));
      endStage("anti-aliasing");
    }
  }
  if (samples > 1) {
    accumulator_->resolve(*target_);
    endStage("anti-aliasing");
  }
  view.jitterClip = glm::vec2(0.0f);  // the frame's view is the unshifted one

  // The frame's statistics are copied out before its image is read and read after it: the image's
  // read is the one wait of the frame (FrameStatistics).
  const bool virtualObjectsRan =
      std::find(plan.passes.begin(), plan.passes.end(), passes::PassId::VirtualObjects) != plan.passes.end();
  readback_.begin();
  // The search pass resets the statistics buffer: a frame without it (every mirror ray-cast) searched nothing.
  const std::size_t searchCopy =
      plan.search ? readback_.copy(reflections_.statistics(), sizeof(passes::SearchStatistics)) : 0;
  const passes::TessellationBuffers& tessellation = reflections_.tessellation();
  const std::size_t totalsCopy =
      plan.tessellate ? readback_.copy(tessellation.totals(), sizeof(passes::gpu::TessellationTotals)) : 0;
  const std::size_t midpointCopy =
      plan.tessellate ? readback_.copy(tessellation.midpointStatistics(), sizeof(passes::SearchStatistics)) : 0;
  if (virtualObjectsRan) virtualObjects_->queueStatistics(readback_);
  readback_.fence();
  RenderedFrame result{width, height,     samples, target_->readRgba(),   {}, {},
                       {},    frame.view, {},      plan.gbufferPrecision, {}, {}};
  if (!readback_.wait()) return Error{"the GPU did not finish the frame (driver: " + context_.info().renderer + ")"};
  for (const passes::PlannedMirror& mirror : plan.mirrors) {
    if (mirror.slots->part == 0) result.drawnMirrors.push_back(mirror.slots->mirrorObject);
    MirrorPlanSummary summary{mirror.slots->mirrorObject,
                              mirror.slots->part,
                              mirror.slots->kind,
                              mirror.method,
                              mirror.projectedPixels,
                              mirror.facesAway,
                              mirror.reflected.size(),
                              0,
                              mirror.culledObjects,
                              mirror.culledVertices,
                              mirror.belowBudgetObjects,
                              mirror.belowBudgetVertices,
                              0,
                              mirror.cost,
                              {}};
    for (const passes::ReflectionSlotRange* range : mirror.reflected) summary.searchedVertices += range->vertexCount;
    result.plan.push_back(summary);
  }
  if (virtualObjectsRan) {
    const std::vector<passes::VirtualObjectsPass::PartStatistics> parts = virtualObjects_->readStatistics(readback_);
    for (std::size_t i = 0; i < parts.size() && i < result.plan.size(); ++i) {
      result.plan[i].uncoveredRayCast = parts[i].uncoveredRayCast;
      result.plan[i].castTiles = parts[i].castTiles;
    }
  }
  endStage("readback");
  if (plan.search) result.search = readback_.read<passes::SearchStatistics>(searchCopy);
  tessellationOutgrown = false;
  if (plan.tessellate) {
    tessellationOutgrown =
        reflections_.tessellation().finishFrame(readback_.read<passes::gpu::TessellationTotals>(totalsCopy),
                                                readback_.read<passes::SearchStatistics>(midpointCopy));
    result.tessellation = tessellation.statistics();
  }

  std::vector<double> times(marks, 0.0);
  for (std::size_t i = 0; timePasses && i < marks; ++i) {
    if (cpuRasterizer_) {
      times[i] = wallMarks[i];
      continue;
    }
    GLuint64 nanoseconds = 0;
    gl.GetQueryObjectui64v(stamps_[i].id(), GL_QUERY_RESULT, &nanoseconds);
    times[i] = static_cast<double>(nanoseconds) * 1e-6;
  }
  // A stage run once per sample point is reported once, its times summed, in the order first run.
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const auto same = [&](const StageTiming& stage) { return stage.name == stages[i]; };
    auto found = std::find_if(result.timings.stages.begin(), result.timings.stages.end(), same);
    if (found == result.timings.stages.end())
      found = result.timings.stages.insert(found, {std::string(stages[i]), 0.0});
    found->milliseconds += times[i + 1] - times[i];
  }
  result.planner.rates = costs_.rates();
  result.planner.explored = role.explore.has_value();
  if (role.measure) learnCosts(plan, result);
  if (const GLenum error = gl.GetError(); error != GL_NO_ERROR)
    return Error{"GL error " + gl::glErrorName(error) + " while rendering (driver: " + context_.info().renderer + ")"};
  result.timings.totalMilliseconds = millisecondsSince(start);
  return result;
}

void Renderer::learnCosts(const passes::FramePlan& plan, RenderedFrame& frame) {
  passes::PartCost fitted;
  RenderedFrame::PlannerCosts& planner = frame.planner;
  for (const passes::PlannedMirror& mirror : plan.mirrors) {
    if (mirror.method == passes::PartMethod::VirtualObjects) {
      fitted.search += mirror.fittedCost.search;
      planner.predicted.search += mirror.cost.search;
    } else if (mirror.method == passes::PartMethod::RayCast) {
      fitted.rayCast += mirror.fittedCost.rayCast;
      planner.predicted.rayCast += mirror.cost.rayCast;
    }
  }
  // The search's own passes are searching; the virtual-objects pass draws the searched parts and
  // casts the others, and is shared between them as the prediction shares it.
  double searching = 0.0, drawing = 0.0;
  for (const StageTiming& stage : frame.timings.stages) {
    using passes::PassId;
    if (stage.name == passes::passName(PassId::VirtualObjects)) drawing += stage.milliseconds;
    for (PassId pass :
         {PassId::GBufferPyramid, PassId::RayHierarchy, PassId::ExplosionMap, PassId::Search, PassId::Tessellation})
      if (stage.name == passes::passName(pass)) searching += stage.milliseconds;
  }
  const double predictedTotal = planner.predicted.search + planner.predicted.rayCast;
  const double searchShare = predictedTotal > 0.0 ? planner.predicted.search / predictedTotal : 0.0;
  planner.took = {fitted.search > 0.0 ? searching + drawing * searchShare : 0.0, drawing * (1.0 - searchShare)};
  planner.measured = true;
  costs_.observe(fitted, planner.took);
}

}  // namespace specula::render
