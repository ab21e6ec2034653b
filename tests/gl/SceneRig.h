#pragma once
// A GL context and a renderer for one scene, and the frame against the ray tracer, as the GL
// tests use them.
#include <gtest/gtest.h>

#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "gl/GlContext.h"
#include "reference/ImageMetrics.h"
#include "reference/RayTracer.h"
#include "render/Renderer.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::testing {

// Default settings, but every visible mirror is searched and drawn as virtual objects alone: the
// planner would ray-cast a mirror where that is cheaper, the virtual-objects pass would ray-cast the
// pixels its triangles leave uncovered, and these tests are about the search and its triangles.
inline passes::ReflectionSettings virtualObjects(passes::ReflectionSettings settings = {}) {
  settings.rayCast = passes::RayCastRule::Never;
  settings.rayCastUncovered = false;
  return settings;
}

// Every way of finding reflection points, for tests that hold each to the same bounds: both searches,
// and the explosion map refined by the crosshair search (the map's look-ups alone have their own,
// wider bounds: tests/gl/ExplosionMapTest.cpp).
inline const std::vector<passes::SearchStrategy> kSearchStrategies(std::begin(passes::kSearchStrategies),
                                                                   std::end(passes::kSearchStrategies));

inline passes::ReflectionSettings withSearch(passes::SearchStrategy search,
                                             passes::ReflectionSettings settings = virtualObjects()) {
  settings.search = search;
  settings.explosionRefine = search == passes::SearchStrategy::ExplosionMap;
  return settings;
}

// A gtest parameter name for a search strategy.
inline std::string searchName(passes::SearchStrategy search) {
  return search == passes::SearchStrategy::ExplosionMap ? "explosion_map_refined" : passes::searchStrategyName(search);
}

struct Rig {
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
};

// Fails the calling test (not fatally) and returns an empty rig when GL or the scene cannot start.
inline Rig makeRig(std::shared_ptr<const scene::Scene> scene) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  EXPECT_TRUE(context) << context.error();
  if (!context) return {};
  auto renderer = render::Renderer::create(**context, std::move(scene));
  EXPECT_TRUE(renderer) << renderer.error();
  if (!renderer) return {};
  return {std::move(context.value()), std::move(renderer.value())};
}

inline Rig makeRig(const std::string& sceneName) {
  return makeRig(std::make_shared<const scene::Scene>(*scene::makeBuiltinScene(sceneName)));
}

struct MirrorMismatch {
  double share = 1.0;  // of the reference's mirror pixels, those the frame gets strongly wrong
  std::size_t mirrorPixels = 0;
  std::vector<std::uint8_t> reference;  // the ray tracer's image, to look at (mismatchAgainstRayTracer only)
};

// The frame against a ray-traced image of the same pose and size (rendered once, compared often).
inline MirrorMismatch mismatchAgainst(const reference::ReferenceImage& reference, const render::RenderedFrame& frame) {
  auto mismatch = reference::maskedMismatch({frame.rgba, frame.width, frame.height},
                                            {reference.rgba, frame.width, frame.height}, reference.mirrorMask);
  EXPECT_TRUE(mismatch) << mismatch.error();
  if (!mismatch) return {};
  return {mismatch->share(), mismatch->inside, {}};
}

// The options that trace what `frame` rasterized: its size and its samples a pixel.
inline reference::RayTracerOptions tracedLike(const render::RenderedFrame& frame) {
  reference::RayTracerOptions options;
  options.width = frame.width;
  options.height = frame.height;
  options.samples = frame.samples;
  return options;
}

// The frame against the ray tracer's image of `truth` at the same pose (and size and samples).
inline MirrorMismatch mismatchAgainstRayTracer(const std::shared_ptr<const scene::Scene>& truth,
                                               const scene::ScenePose& pose, const render::RenderedFrame& frame) {
  auto tracer = reference::RayTracer::create(truth);
  EXPECT_TRUE(tracer) << tracer.error();
  if (!tracer) return {};
  auto reference = (*tracer)->render(pose, tracedLike(frame));
  EXPECT_TRUE(reference) << reference.error();
  if (!reference) return {};
  MirrorMismatch result = mismatchAgainst(*reference, frame);
  result.reference = std::move(reference->rgba);
  return result;
}

}  // namespace specula::testing
