#pragma once
// Where each (mirror, reflected object) pair keeps its reflected vertices in the GPU buffer.
// Fixed per scene, so a vertex finds last frame's texel in the same slot (frame-to-frame coherence).
#include <cstdint>
#include <vector>

#include "scene/Scene.h"

namespace specula::passes {

struct ReflectionSlotRange {
  std::size_t object = 0;       // index into Scene::objects
  std::uint32_t firstSlot = 0;  // first of the object's vertex count slots
};

struct MirrorSlots {
  std::size_t mirrorObject = 0;  // index into Scene::objects
  int layer = 0;                 // G-buffer layer; the mirror's stencil value is layer + 1
  std::vector<ReflectionSlotRange> reflected;
};

struct ReflectionSlots {
  std::vector<MirrorSlots> mirrors;
  std::uint32_t slotCount = 0;

  // Every mirror reflects every other object that has `reflected` set (other mirrors included,
  // with their own colour: no inter-reflections).
  static ReflectionSlots forScene(const scene::Scene& scene);
};

}  // namespace specula::passes
