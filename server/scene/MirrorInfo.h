#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

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
};

// What makes an object a mirror. Open mirrors (a bowl, a half-pipe) are searched on a closed twin mesh.
struct MirrorInfo {
  MirrorCurvature curvature = MirrorCurvature::Convex;
  bool closed = true;
  std::optional<std::uint32_t> closedTwinMesh;  // index into Scene::meshes; set exactly when !closed
  std::optional<AnalyticShape> analytic;
};

}  // namespace specula::scene
