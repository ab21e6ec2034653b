#pragma once
// The session layer's view of a renderer: one call renders one posed frame for one session.
// Implemented with GL by GlFrameRenderer and by fakes in tests.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "base/Result.h"
#include "passes/ReflectionSettings.h"
#include "scene/ScenePose.h"
#include "specula.pb.h"

namespace specula::session {

struct RenderJob {
  std::uint64_t session = 0;  // lets a renderer keep per-view state (search coherence) per session
  scene::ScenePose pose;
  int width = 0, height = 0;
  passes::ReflectionSettings settings;
  int samples = 1;  // anti-aliasing: samples a pixel (math::samplePattern)

  bool operator==(const RenderJob&) const = default;
};

struct RenderOutput {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;                       // sRGB, row 0 at the top
  std::vector<std::pair<std::string, double>> stageMs;  // GPU time per stage
  double renderMs = 0.0;                                // wall clock
  v1::SearchStatistics search;
  v1::TessellationStatistics tessellation;
  std::vector<v1::MirrorPlan> plan;
};

class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  virtual Result<RenderOutput> render(const RenderJob& job) = 0;
};

// Creates a renderer on the thread that will use it (a GL context is bound to its thread).
using FrameRendererFactory = std::function<Result<std::unique_ptr<FrameRenderer>>()>;

}  // namespace specula::session
