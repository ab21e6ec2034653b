#pragma once
// The search's reflection points against the exact solvers (server/math: spheres, extrusions and
// Bézier patches), in screen pixels.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "render/Renderer.h"
#include "scene/ScenePose.h"

namespace specula::bench {

// Where a world point lands in a width × height frame of `view`, in pixels (x right, y down from
// the top row; pixel centres at half-integers). Meaningless for points behind the eye.
glm::dvec2 toPixels(const passes::FrameView& view, const glm::vec3& world, int width, int height);

// One vertex both the search and the exact solver call visible, on screen in pixels.
struct MeasuredVertex {
  std::size_t slot;   // its reflection slot
  glm::dvec2 exact;   // exact R
  glm::dvec2 offset;  // search R − exact R
};

struct ReflectionPointErrors {
  std::vector<double> pixels;  // |offset| of each measured vertex, in the order of `vertices`
  std::vector<MeasuredVertex> vertices;
  int exactHiddenButSearchVisible = 0;  // reflected although no reflection point exists
  int searchHiddenButExactVisible = 0;  // dropped although its reflection is visible
  // Of the latter, those whose exact reflection point is within kNearSilhouetteCosine of grazing:
  // where a mesh's polygonal outline and the exact shape's disagree.
  int searchHiddenNearSilhouette = 0;
  static constexpr double kNearSilhouetteCosine = 0.1;  // the eye sees the point within ~6° of grazing

  // The p-quantile (0 ≤ p ≤ 1) of `pixels`; 0 when there are none.
  double percentile(double p) const;
  double mean() const;
};

// Compares the last frame's search results (a GPU readback) with the exact reflection point on
// every mirror with an exact shape (an analytic sphere, a declared extrusion or Bézier patches; each
// part of a parametric mirror against its own patches), for every vertex whose exact reflection
// point lies inside the frame (plus `marginPixels`). Other mirrors are skipped.
ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                              const render::RenderedFrame& frame, double marginPixels = 0.0);

// The same for every vertex the last frame's tessellation finished (its corners and the midpoints it
// added), when it was tessellated; MeasuredVertex::slot is then the vertex's index in the lists.
ReflectionPointErrors measureTessellatedPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                               const render::RenderedFrame& frame, double marginPixels = 0.0);

// True when the scene has a mirror measureReflectionPoints can measure.
bool hasExactMirror(const scene::Scene& scene);

}  // namespace specula::bench
