#pragma once
// FrameRenderer on the GL Renderer: one GL context and one Renderer per render thread, shared by the
// sessions that thread serves. Search coherence belongs to one view: each session's is parked while
// others render, so switching back resumes warm.
#include <deque>
#include <memory>
#include <utility>

#include "gl/GlContext.h"
#include "render/Renderer.h"
#include "session/FrameRenderer.h"

namespace specula::session {

class GlFrameRenderer : public FrameRenderer {
 public:
  // `context` must be current on the calling thread, which is the thread that will render.
  static Result<std::unique_ptr<FrameRenderer>> create(std::unique_ptr<gl::GlContext> context,
                                                       std::shared_ptr<const scene::Scene> scene);
  ~GlFrameRenderer() override;

  Result<RenderOutput> render(const RenderJob& job) override;

 private:
  GlFrameRenderer(std::unique_ptr<gl::GlContext> context, std::unique_ptr<render::Renderer> renderer)
      : context_(std::move(context)), renderer_(std::move(renderer)) {}

  // At most this many sessions keep their search state parked (each slot-count × 64 bytes of GPU
  // memory); the least recently rendered one starts cold again.
  static constexpr std::size_t kMaxParkedViews = 16;

  std::unique_ptr<gl::GlContext> context_;
  std::unique_ptr<render::Renderer> renderer_;  // destroyed before the context
  std::uint64_t lastSession_ = 0;
  std::deque<std::pair<std::uint64_t, render::Renderer::ViewCoherence>> parked_;  // most recent last
};

}  // namespace specula::session
