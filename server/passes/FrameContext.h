#pragma once
// What every pass of one frame sees: the GL context, the scene at this instant, the view, the
// plan, the target and the reflection state kept between frames.
#include <glm/glm.hpp>
#include <vector>

#include "gl/GlApi.h"
#include "gl/RenderTarget.h"
#include "gl/ShaderProgram.h"
#include "math/Bounds.h"
#include "passes/FramePlan.h"
#include "passes/GpuMeshes.h"
#include "passes/GpuTextures.h"
#include "passes/ReflectionResources.h"
#include "passes/ReflectionSettings.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::passes {

// The eye's view and projection for this frame.
struct FrameView {
  glm::mat4 worldToView{1.0f};
  float fovYDegrees = 45.0f;
  float aspect = 1.0f;  // width / height
  float nearDistance = 0.1f, farDistance = 100.0f;
  // Anti-aliased frames: the sample point's offset from the pixel centre, in clip x and y (the whole
  // projection moves with it, so every pass and the G-buffer see the same shifted pixel grid).
  glm::vec2 jitterClip{0.0f};

  // worldToClip with the image plane widened by `widen` (1 = the frame itself) and the far plane
  // moved to farScale × farDistance.
  glm::mat4 worldToClip(glm::vec2 widen = glm::vec2(1.0f), float farScale = 1.0f) const;
  // Radians one pixel of a frame `height` pixels tall spans on the view axis.
  float pixelAngle(int height) const;
  // The view axis, world, unit.
  glm::vec3 forward() const;
};

struct FrameContext {
  const gl::GlApi& gl;
  const scene::Scene& scene;
  const scene::ScenePose& pose;
  const std::vector<math::Bounds>& worldBounds;  // per object, at this pose
  const GpuMeshes& meshes;
  const GpuTextures& textures;
  const FrameView& view;
  const FramePlan& plan;
  const ReflectionSettings& settings;
  const gl::RenderTarget& target;
  ReflectionResources& reflections;

  // The object's mesh a mirror search runs on: its closed twin when the mirror is open.
  std::size_t searchMesh(std::size_t mirrorObject) const;
  // The eye's projection onto the G-buffer: the frame's, widened by the G-buffer's margin.
  glm::mat4 gbufferWorldToClip() const;
  // Sets objectToWorld, normalToWorld and firstSlot: the uniforms naming one reflected object
  // and its search slots, for every program that reads them.
  void setReflectedObject(const gl::ShaderProgram& program, const ReflectionSlotRange& range) const;
};

}  // namespace specula::passes
