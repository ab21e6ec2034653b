#pragma once
// The frame graph as plain data: which passes run and which mirrors they serve, decided per frame
// from what the camera sees, so a frame without a visible mirror runs no reflection pass at all.
#include <string_view>
#include <vector>

#include "math/Bounds.h"
#include "math/Camera.h"
#include "passes/ReflectionSettings.h"
#include "passes/ReflectionSlots.h"

namespace specula::passes {

struct FramePlan {
  std::vector<std::string_view> passes;         // pass names in execution order
  std::vector<const MirrorSlots*> mirrors;      // visible mirrors whose reflections are drawn
  bool tessellate = false;                      // virtual objects come from the tessellation pass
  // The settings' precision, unless RGBA16F cannot place a visible mirror's texels (far from the origin).
  GBufferPrecision gbufferPrecision = GBufferPrecision::Float32;
};

// Whether half floats resolve positions on a mirror with these world bounds finely enough for the
// search: their spacing at the mirror's largest coordinate must stay under ~1/100 of its radius.
bool halfFloatsResolve(const math::Bounds& mirrorBounds);

// worldBounds: one box per scene object at this frame's pose. aspect = width / height.
FramePlan planFrame(const ReflectionSlots& slots, const std::vector<math::Bounds>& worldBounds,
                    const math::Camera& camera, float aspect, const ReflectionSettings& settings);

// Whether a world-space box can be seen through the camera's frustum widened by `margin`.
bool boundsInFrustum(const math::Bounds& bounds, const math::Camera& camera, float aspect, float margin);

}  // namespace specula::passes
