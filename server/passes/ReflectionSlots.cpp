#include "passes/ReflectionSlots.h"

#include "scene/Deformation.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "passes/QuadricUniforms.h"

namespace specula::passes {

namespace {

float longestEdge(const scene::Mesh& mesh) {
  float longest = 0.0f;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (std::size_t e = 0; e < 3; ++e)
      longest = std::max(longest, glm::distance(mesh.vertices[mesh.indices[t + e]].position,
                                                mesh.vertices[mesh.indices[t + (e + 1) % 3]].position));
  return longest;
}

}  // namespace

ReflectionSlots ReflectionSlots::forScene(const scene::Scene& scene) {
  ReflectionSlots slots;
  std::vector<float> longestEdges;
  for (const scene::Mesh& mesh : scene.meshes) longestEdges.push_back(longestEdge(mesh));
  int stencil = 0;
  for (std::size_t m = 0; m < scene.objects.size(); ++m) {
    const scene::SceneObject& object = scene.objects[m];
    if (!object.mirror || scene.materials[object.material].reflectivity <= 0.0f) continue;
    ++stencil;
    const scene::MirrorInfo& info = *object.mirror;
    const bool exactQuadric = info.exactQuadric();
    scene::MirrorParts parts{{scene::MirrorPart{scene::SurfaceKind::Convex, 0}}, {}};
    if (!exactQuadric) {
      parts = scene::MirrorParts::of(scene.meshes[info.closedTwinMesh.value_or(object.mesh)], info.curvature);
      slots.parts.emplace(m, parts);
    }
    const bool deforms = scene::deforms(scene, m);
    // Seen from behind, a two-sided mirror's convex side is concave; a deforming mirror's curvature changes:
    // their parts are planned as saddles.
    if (info.twoSided() || deforms)
      for (scene::MirrorPart& part : parts.parts) part.kind = scene::SurfaceKind::Saddle;
    const bool seesItself = object.reflected && !exactQuadric && (deforms || !parts.cannotSeeItself(info.closed));
    for (std::size_t p = 0; p < parts.parts.size(); ++p) {
      MirrorReach reach = exactQuadric
                              ? MirrorReach::ofQuadric(*info.analytic)
                              : MirrorReach::ofMeshPart(scene.meshes[info.closedTwinMesh.value_or(object.mesh)], parts,
                                                        p, parts.cannotSeeItself(info.closed));
      if (info.twoSided()) reach.normalCosine = -1.0f;  // its normals, turned to the eye, point either way
      if (deforms) reach = MirrorReach{};               // its rest shape bounds nothing of the frame's
      MirrorSlots mirror{m,
                         static_cast<int>(slots.mirrors.size()),
                         stencil,
                         static_cast<int>(p),
                         static_cast<int>(parts.parts.size()),
                         parts.parts[p].kind,
                         seesItself,
                         reach,
                         {},
                         info.extrusion.has_value(),
                         info.twoSided(),
                         deforms};
      for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        if (o == m || !scene.objects[o].reflected) continue;
        const scene::Mesh& mesh = scene.meshes[scene.objects[o].mesh];
        const auto vertexCount = static_cast<std::uint32_t>(mesh.vertices.size());
        mirror.reflected.push_back({o, slots.slotCount, vertexCount, static_cast<std::uint32_t>(mesh.triangleCount()),
                                    longestEdges[scene.objects[o].mesh]});
        slots.slotCount += vertexCount;
      }
      slots.mirrors.push_back(std::move(mirror));
    }
  }
  return slots;
}

}  // namespace specula::passes
