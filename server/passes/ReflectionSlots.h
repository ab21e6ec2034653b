#pragma once
// Where each (mirror part, reflected object) pair keeps its reflected vertices in the GPU buffer.
// Fixed per scene, so a vertex finds last frame's texel in the same slot (frame-to-frame coherence).
#include <cstdint>
#include <map>
#include <vector>

#include "passes/MirrorReach.h"
#include "scene/MirrorParts.h"
#include "scene/Scene.h"

namespace specula::passes {

struct ReflectionSlotRange {
  std::size_t object = 0;       // index into Scene::objects
  std::uint32_t firstSlot = 0;  // first of the object's vertex count slots
  std::uint32_t vertexCount = 0;
  std::uint32_t triangleCount = 0;  // the object's mesh's: what its search would tessellate and draw
  float longestEdge = 0.0f;         // the mesh's longest triangle edge, object space: bounds its images' bends
};

// One part of a mirror (scene::MirrorParts): its own G-buffer layer, search and reflection.
struct MirrorSlots {
  std::size_t mirrorObject = 0;  // index into Scene::objects
  int layer = 0;                 // G-buffer layer of this part
  int stencil = 1;               // the mirror's stencil value, shared by its parts
  int part = 0, partCount = 1;   // which part of the mirror's search mesh
  scene::SurfaceKind kind = scene::SurfaceKind::Convex;
  bool seesItself = false;  // reflected rays may meet this mirror again: its own mesh is ray-cast
  MirrorReach reach;        // where its reflected rays can go (object space): the plan culls with it
  std::vector<ReflectionSlotRange> reflected;
  // Declared a linear extrusion (scene::MirrorInfo::extrusion): the search can solve it exactly and
  // then needs none of a strategy's structures (ReflectionSettings::solveExtrusions).
  bool extrusion = false;
  // An open mirror with no closed twin (scene::MirrorInfo::twoSided): its parts are always ray-cast,
  // seen from either side, so they are saddles reaching every way.
  bool twoSided = false;
  // A mirror that changes shape (scene::deforms): its parts were found on its rest shape and their
  // curvature can change as it deforms, so they are always ray-cast, as saddles reaching every way, and
  // planned within the mirror's bounds of the frame (reach.bounds is empty).
  bool deforms = false;
};

struct ReflectionSlots {
  static constexpr int kMaxMirrors = 255;  // stencil values 1..255

  std::vector<MirrorSlots> mirrors;  // one per part, a mirror's parts in a row
  std::uint32_t slotCount = 0;
  // The parts of each mirror object's search mesh; analytic mirrors (one exact convex quadric) have none.
  std::map<std::size_t, scene::MirrorParts> parts;

  // Every mirror reflects every other object that has `reflected` set (other mirrors included,
  // with their own colour: no inter-reflections). A mesh mirror is split into parts of one
  // curvature each; a mirror that is itself reflected and can meet its own reflected rays (not one
  // closed convex part) shows its own colour where they do.
  static ReflectionSlots forScene(const scene::Scene& scene);
};

}  // namespace specula::passes
