#pragma once
// Shared set-up of the reflection tests: a renderer for a built-in scene on a software platform,
// and the search's reflection points measured against the exact sphere solver in pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "gl/GlContext.h"
#include "math/SphereReflection.h"
#include "render/Renderer.h"
#include "scene/ScenePose.h"
#include "scene/builtin/BuiltinScenes.h"

namespace specula::testing {

// Where a world point lands in the frame, in pixels (x right, y down from the top row).
inline glm::dvec2 toPixels(const passes::FrameView& view, const glm::vec3& world, int width, int height) {
  const glm::vec4 clip = view.worldToClip() * glm::vec4(world, 1.0f);
  const glm::dvec2 ndc = glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w);
  return {(ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
}

struct ReflectionPointErrors {
  std::vector<double> pixels;         // |search R − exact R| on screen, for vertices both call visible
  std::map<std::size_t, glm::dvec2> exactBySlot;   // exact R on screen, by reflection slot
  std::map<std::size_t, glm::dvec2> offsetBySlot;  // search R − exact R on screen, by reflection slot
  int exactHiddenButSearchVisible = 0;
  int searchHiddenButExactVisible = 0;
  double percentile(double p) const {
    if (pixels.empty()) return 0.0;
    std::vector<double> sorted = pixels;
    std::sort(sorted.begin(), sorted.end());
    return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(p * static_cast<double>(sorted.size())))];
  }
};

// Compares every search result of the last frame with the exact reflection point on each analytic
// sphere mirror. Only reflection points inside the frame (plus `marginPixels`) are measured.
inline ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                                     const render::RenderedFrame& frame, double marginPixels = 0.0) {
  ReflectionPointErrors errors;
  const std::vector<passes::ReflectedVertex> results = renderer.readReflectedVertices();
  const scene::Scene& scene = renderer.scene();
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    const scene::SceneObject& mirrorObject = scene.objects[mirror.mirrorObject];
    if (!mirrorObject.mirror || !mirrorObject.mirror->analytic) continue;
    const glm::mat4& mirrorToWorld = pose.objectToWorld[mirror.mirrorObject];
    const math::Sphere sphere{glm::dvec3(mirrorToWorld * glm::vec4(mirrorObject.mirror->analytic->center, 1.0f)),
                              mirrorObject.mirror->analytic->radii.x * glm::length(glm::vec3(mirrorToWorld[0]))};
    for (const passes::ReflectionSlotRange& range : mirror.reflected) {
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const passes::ReflectedVertex& result = results[range.firstSlot + v];
        const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
        const auto exact = math::sphereReflectionPoint(sphere, glm::dvec3(pose.camera.eye), vertex);
        const bool searchVisible = (result.state.w & (passes::ReflectedVertex::kHidden | passes::ReflectedVertex::kUnsolved)) == 0;
        if (!exact) {
          errors.exactHiddenButSearchVisible += searchVisible;
          continue;
        }
        const glm::dvec2 exactPixel = toPixels(frame.view, glm::vec3(*exact), frame.width, frame.height);
        if (exactPixel.x < -marginPixels || exactPixel.y < -marginPixels || exactPixel.x > frame.width + marginPixels ||
            exactPixel.y > frame.height + marginPixels)
          continue;
        if (!searchVisible) {
          errors.searchHiddenButExactVisible++;
          continue;
        }
        const glm::dvec2 offset = toPixels(frame.view, glm::vec3(result.reflectionPoint), frame.width, frame.height) - exactPixel;
        errors.pixels.push_back(glm::length(offset));
        errors.exactBySlot[range.firstSlot + v] = exactPixel;
        errors.offsetBySlot[range.firstSlot + v] = offset;
      }
    }
  }
  return errors;
}

}  // namespace specula::testing
