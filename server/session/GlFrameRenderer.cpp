#include "session/GlFrameRenderer.h"

#include <chrono>

namespace specula::session {

Result<std::unique_ptr<FrameRenderer>> GlFrameRenderer::create(std::unique_ptr<gl::GlContext> context,
                                                               std::shared_ptr<const scene::Scene> scene) {
  auto renderer = render::Renderer::create(*context, std::move(scene));
  if (!renderer) return Error{renderer.error()};
  return std::unique_ptr<FrameRenderer>(new GlFrameRenderer(std::move(context), std::move(*renderer)));
}

GlFrameRenderer::~GlFrameRenderer() {
  parked_.clear();  // GL buffers: before the renderer and its context
  renderer_.reset();
}

Result<RenderOutput> GlFrameRenderer::render(const RenderJob& job) {
  if (job.session != lastSession_) {
    // Park the last session's search state and resume this one's (cold if it has none).
    render::Renderer::ViewCoherence resumed;
    for (auto it = parked_.begin(); it != parked_.end(); ++it)
      if (it->first == job.session) {
        resumed = std::move(it->second);
        parked_.erase(it);
        break;
      }
    parked_.emplace_back(lastSession_, renderer_->exchangeCoherence(std::move(resumed)));
    if (parked_.size() > kMaxParkedViews) parked_.pop_front();
    lastSession_ = job.session;
  }
  const auto start = std::chrono::steady_clock::now();
  auto frame = renderer_->render(job.pose, job.width, job.height, job.settings, job.samples);
  if (!frame) return Error{frame.error()};
  RenderOutput out;
  out.renderMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out.width = frame->width;
  out.height = frame->height;
  out.rgba = std::move(frame->rgba);
  for (const render::StageTiming& stage : frame->timings.stages)
    out.stageMs.emplace_back(stage.name, stage.milliseconds);
  const passes::SearchStatistics& search = frame->search;
  out.search.set_mirrors(static_cast<std::uint32_t>(frame->drawnMirrors.size()));
  out.search.set_searched(search.searched);
  out.search.set_mean_steps(search.searched ? static_cast<double>(search.totalSteps) / search.searched : 0.0);
  out.search.set_max_steps(search.maxSteps);
  out.search.set_cold_starts(search.coldStarts);
  out.search.set_hidden(search.hidden);
  out.search.set_unsolved(search.unsolved);
  out.search.set_enlarged(search.enlarged);
  out.search.set_in_no_cone(search.inNoCone);
  const passes::TessellationStatistics& tessellation = frame->tessellation;
  out.tessellation.set_input_triangles(tessellation.inputTriangles);
  out.tessellation.set_finished_triangles(tessellation.finishedTriangles);
  out.tessellation.set_midpoint_searches(tessellation.midpointSearches.searched);
  out.tessellation.set_capped(tessellation.capped);
  for (const render::MirrorPlanSummary& mirror : frame->plan) {
    v1::MirrorPlan& plan = out.plan.emplace_back();
    plan.set_mirror(renderer_->scene().objects[mirror.mirrorObject].name);
    plan.set_part(static_cast<std::uint32_t>(mirror.part));
    plan.set_faces_away(mirror.facesAway);
    plan.set_method(passes::partMethodName(mirror.method));
    plan.set_searched_objects(static_cast<std::uint32_t>(mirror.searchedObjects));
    plan.set_searched_vertices(static_cast<std::uint32_t>(mirror.searchedVertices));
    plan.set_culled_objects(static_cast<std::uint32_t>(mirror.culledObjects));
    plan.set_culled_vertices(static_cast<std::uint32_t>(mirror.culledVertices));
    plan.set_uncovered_ray_cast(static_cast<std::uint32_t>(mirror.uncoveredRayCast));
    plan.set_below_budget_objects(static_cast<std::uint32_t>(mirror.belowBudgetObjects));
    plan.set_below_budget_vertices(static_cast<std::uint32_t>(mirror.belowBudgetVertices));
  }
  return out;
}

}  // namespace specula::session
