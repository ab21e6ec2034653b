#pragma once
// Runs the passes a frame needs for one view and reads the frame back.
// Owns GL resources: create, use and destroy it on the thread where its context is current.
// Keeps per-view reflection state (last frame's reflection texels), so one Renderer serves one view.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "gl/GlContext.h"
#include "gl/GpuReadback.h"
#include "gl/RenderTarget.h"
#include "math/Bounds.h"
#include "passes/FrameContext.h"
#include "passes/GpuMeshes.h"
#include "passes/GpuDeformation.h"
#include "passes/GpuTextures.h"
#include "passes/MeasuredCosts.h"
#include "passes/Pass.h"
#include "passes/PatchTessellation.h"
#include "passes/ReflectionResources.h"
#include "passes/ReflectionSettings.h"
#include "passes/ReflectionSlots.h"
#include "render/FrameTimings.h"
#include "render/SampleAccumulator.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::passes {
class VirtualObjectsPass;
}

namespace specula::render {

// One visible mirror part's share of the frame plan: the reflected objects searched, and those left
// out because they cannot appear in it (behind every tangent plane, or in its shadow from the eye).
struct MirrorPlanSummary {
  std::size_t mirrorObject = 0;  // index into Scene::objects
  int part = 0;
  scene::SurfaceKind kind = scene::SurfaceKind::Convex;
  passes::PartMethod method = passes::PartMethod::VirtualObjects;
  double projectedPixels = 0.0;  // the mirror's bounds on screen, about: what the method was chosen by
  bool facesAway = false;        // the eye sees only its back: nothing searched
  std::size_t searchedObjects = 0, searchedVertices = 0;
  std::size_t culledObjects = 0, culledVertices = 0;
  std::size_t belowBudgetObjects = 0, belowBudgetVertices = 0;  // images smaller than the error budget
  std::size_t uncoveredRayCast = 0;  // pixels no virtual object covered, ray-cast instead (searched parts)
  passes::PartCost predictedCost;    // what chose between searching and ray-casting
  // Ray-cast parts: the 8×8 tiles its objects were cast on, of objects × the part's tiles.
  passes::CastTileCount castTiles;
};

struct RenderedFrame {
  int width = 0, height = 0;
  int samples =
      1;  // anti-aliasing: the passes ran once per sample point, their times summed; statistics are the last run's
  std::vector<std::uint8_t> rgba;  // sRGB, tightly packed, row 0 at the top
  FrameTimings timings;
  std::vector<std::size_t> drawnMirrors;        // scene object indices of the mirrors searched and drawn
  passes::SearchStatistics search;              // zero when no mirror was visible
  passes::FrameView view;                       // the camera matrices used (for measuring in pixels)
  passes::TessellationStatistics tessellation;  // empty when the frame was not tessellated
  // What the G-buffer used: RGBA16F falls back to RGBA32F for mirrors far from the origin.
  passes::GBufferPrecision gbufferPrecision = passes::GBufferPrecision::Float32;
  std::vector<MirrorPlanSummary> plan;  // per visible mirror part, a mirror's parts in a row
  // The planner on this device (passes::MeasuredCosts): the rates its plan used and, on a frame it
  // measured, what the parts' methods were predicted to cost (those rates) and took, per method.
  struct PlannerCosts {
    passes::CostRates rates;
    bool measured = false;  // timed pass by pass for the planner
    bool explored = false;  // every part took the method the planner did not choose
    passes::PartCost predicted, took;
  } planner;
};

// How a frame's stages are timed.
enum class PassTiming {
  // Each pass on its own: GPU timestamps, or on a CPU rasterizer glFinish after each pass (which
  // keeps the rasterizer from overlapping passes, so the frame takes longer).
  PerPass,
  // The frame's wall time only; the stages are named, at 0 ms. No wait but the final image's read.
  FrameOnly,
};

class Renderer {
 public:
  // Uploads the scene's meshes and builds every pass's program; fails on shader errors.
  static Result<std::unique_ptr<Renderer>> create(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene);
  ~Renderer();

  // Renders the scene at `pose` (its camera included) into a width × height frame, anti-aliased with
  // `samples` points a pixel (math::samplePattern; 1, 2, 4, 8 or 16): the passes run once per point.
  Result<RenderedFrame> render(const scene::ScenePose& pose, int width, int height,
                               const passes::ReflectionSettings& settings = {}, int samples = 1);

  // Forgets last frame's reflection texels: the next frame's searches start cold.
  void resetCoherence() { reflections_.resetCoherence(); }
  // One view's search state (each reflected vertex's last texel), parked while other views render.
  struct ViewCoherence {
    std::optional<gl::GlBuffer> reflectedVertices;  // empty: a view not rendered yet, starting cold
  };
  // Hands over the current view's search state and continues from `next`'s: a view rendered before
  // resumes warm.
  ViewCoherence exchangeCoherence(ViewCoherence next) {
    return {reflections_.exchangeReflectedVertices(std::move(next.reflectedVertices))};
  }
  // The last frame's search results, one per slot of reflectionSlots() (a GPU readback).
  std::vector<passes::ReflectedVertex> readReflectedVertices() const { return reflections_.readReflectedVertices(); }
  // One level of the last frame's ray hierarchy (a GPU readback; --search hierarchy only).
  passes::ReflectionResources::RayHierarchyLevel readRayHierarchyLevel(int level) const {
    return reflections_.readRayHierarchyLevel(level);
  }
  int rayHierarchyTopLevel() const { return reflections_.rayHierarchyTopLevel(); }
  // The last frame's tessellated vertices (midpoints included), when it was tessellated.
  std::vector<passes::FinishedVertex> readTessellatedVertices() const {
    return reflections_.tessellation().readFinished();
  }
  const passes::ReflectionSlots& reflectionSlots() const { return slots_; }
  // What the patch tessellation makes of the scene's parametric meshes in `frame`'s view (rendered
  // at `pose`): triangles and their areas in pixels. Fails only if the probe's shaders do not build.
  Result<passes::PatchTessellationMeasure> measurePatchTessellation(const scene::ScenePose& pose,
                                                                    const RenderedFrame& frame);
  const scene::Scene& scene() const { return *scene_; }
  void setPassTiming(PassTiming timing) { passTiming_ = timing; }
  // Every pass, by PassId.
  using PassTable = std::array<std::unique_ptr<passes::Pass>, passes::kPassIds.size()>;

 private:
  using Clock = std::chrono::steady_clock;
  Renderer(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene, passes::ReflectionSlots slots,
           passes::GpuDeformation deformation);
  passes::FrameView frameView(const math::Camera& camera, const std::vector<math::Bounds>& worldBounds,
                              float aspect) const;
  // One try at render(): `tessellationOutgrown` says the frame's tessellation found its lists too
  // small (they have grown since) and the frame is to be drawn again.
  Result<RenderedFrame> renderOnce(const scene::ScenePose& pose, int width, int height,
                                   const passes::ReflectionSettings& settings, int samples,
                                   passes::MeasuredCosts::FrameRole role, Clock::time_point start,
                                   bool& tessellationOutgrown);
  // Teaches costs_ what a measured frame's methods took, from its pass times.
  void learnCosts(const passes::FramePlan& plan, RenderedFrame& frame);

  gl::GlContext& context_;
  std::shared_ptr<const scene::Scene> scene_;
  passes::GpuMeshes meshes_;
  passes::GpuDeformation deformation_;  // writes deforming meshes into meshes_ before each frame's passes
  passes::GpuTextures textures_;
  std::vector<math::Bounds> meshBounds_;  // object space, per mesh
  passes::ReflectionSlots slots_;
  passes::ReflectionResources reflections_;
  PassTable passes_;
  passes::VirtualObjectsPass* virtualObjects_ = nullptr;  // in passes_
  std::optional<gl::RenderTarget> target_;                // kept while frames keep its size
  std::optional<SampleAccumulator> accumulator_;          // built on the first anti-aliased frame
  gl::GpuReadback readback_;                              // the frame's statistics
  std::vector<gl::GlQuery> stamps_;                       // timestamp queries, grown to the longest plan
  PassTiming passTiming_ = PassTiming::PerPass;
  passes::MeasuredCosts costs_;                               // the planner's rates on this device
  std::optional<passes::PatchTessellationProbe> patchProbe_;  // built on first use
  bool cpuRasterizer_ = false;  // Mesa's software rasterizers: passes are timed by the wall clock
};

}  // namespace specula::render
