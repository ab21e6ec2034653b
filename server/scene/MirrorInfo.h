#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

#include "math/ExtrusionReflection.h"

namespace specula::scene {

// How the renderer treats a mesh mirror (scene::MirrorParts): convex or concave declares it one part
// of that curvature; mixed splits it into parts of one curvature each, found from its normals.
enum class MirrorCurvature { Convex, Concave, Mixed };

// An exact description of the mirror surface in object space, so exact solvers can serve as references.
struct AnalyticShape {
  enum class Kind { Sphere, Ellipsoid };
  Kind kind = Kind::Sphere;
  glm::vec3 center{0.0f};
  glm::vec3 radii{1.0f};  // a sphere has three equal radii
  // true: the quadric is the mirror's surface for the renderer and the ray tracer (its mesh only
  // bounds it); false: the mesh is the surface, and the quadric is only the exact answer that
  // reflection-point errors are measured against (a tessellated sphere).
  bool exactSurface = true;
};

// What makes an object a mirror. Open mirrors (a bowl, a half-pipe) are searched on a closed twin mesh;
// one without a twin (an open chrome mesh from a glTF file) reflects on both sides and is ray-cast.
struct MirrorInfo {
  MirrorCurvature curvature = MirrorCurvature::Convex;
  bool closed = true;
  std::optional<std::uint32_t> closedTwinMesh;  // index into Scene::meshes; only for open mirrors
  std::optional<AnalyticShape> analytic;
  // A convex mirror that is a linear extrusion of an ellipse (a cylinder), in object space: the mesh
  // is its surface; the search may solve its reflection points exactly by Ofek & Rappoport's 2-D
  // reduction (ReflectionSettings::solveExtrusions), and reflection-point errors are measured against it.
  std::optional<math::Extrusion> extrusion;

  // Whether renderer and ray tracer use the analytic quadric as the surface: a closed mirror whose
  // shape says so (an open one's quadric would cover where its mesh has no surface).
  bool exactQuadric() const { return analytic && analytic->exactSurface && closed; }
  // Open with no closed twin to search: both sides reflect, every pixel's reflected ray is cast.
  bool twoSided() const { return !closed && !closedTwinMesh; }
};

}  // namespace specula::scene
