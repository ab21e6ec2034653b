#pragma once
// One pose of a scene as an Embree scene: world-space triangles for meshes, exact quadrics (Embree user
// geometry, double precision) for closed mirrors with an analytic shape, which replace their meshes, and
// exact Bézier patches (user geometry too) for parametric meshes, which replace their grids.
#include <embree3/rtcore.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "base/Result.h"
#include "reference/AnalyticSurface.h"
#include "reference/PatchSurface.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::reference {

// Ray mask bits: which rays see an object.
inline constexpr unsigned kSeenDirectly = 1u;   // every object
inline constexpr unsigned kSeenInMirrors = 2u;  // objects with SceneObject::reflected

struct Ray {
  glm::vec3 origin{0.0f};     // world
  glm::vec3 direction{0.0f};  // world, unit
};

// A ray leaving analytic geometry `geometry` (an Embree geometry ID of this scene) at `exit`.
struct Departure {
  unsigned geometry = 0;
  SurfaceExit exit;
};

struct SurfaceHit {
  std::uint32_t object = 0;         // index into Scene::objects
  glm::dvec3 position{0.0};         // world
  glm::dvec3 geometricNormal{0.0};  // world, unit: the triangle's winding normal or the quadric's outward one
  glm::dvec3 shadingNormal{0.0};    // world, not unit: interpolated like the rasterizer's, or the exact normal
  glm::vec2 uv{0.0f};
  float uvPerMetre =
      0.0f;  // how fast uv changes across the hit triangle; 0 on exact surfaces (textures at their finest)
  std::optional<unsigned> analyticGeometry;  // the geometry ID when the hit is on an analytic surface or patches
};

class PosedScene {
 public:
  // `scene` must pass scene::sceneProblem() and outlive the result; `pose` must belong to it.
  static Result<std::unique_ptr<PosedScene>> build(RTCDevice device, const scene::Scene& scene,
                                                   const scene::ScenePose& pose);
  ~PosedScene();
  PosedScene(const PosedScene&) = delete;
  PosedScene& operator=(const PosedScene&) = delete;

  // Nearest hit at t > 0 on objects whose mask shares a bit with `mask`. `departure` keeps a ray that
  // left an analytic surface from meeting it again at its own start. Safe to call from many threads.
  std::optional<SurfaceHit> intersect(const Ray& ray, unsigned mask, const Departure* departure) const;

 private:
  // What an Embree geometry ID stands for.
  struct Geometry {
    std::uint32_t object = 0;
    std::optional<AnalyticSurface> analytic;      // set: user geometry; unset: the object's triangle mesh
    std::shared_ptr<const PatchSurface> patches;  // set: user geometry of the mesh's exact patches
    const scene::Mesh* mesh = nullptr;
    const glm::vec3* worldPositions = nullptr;  // Embree's vertex buffer, one per mesh vertex
    glm::mat3 normalToWorld{1.0f};
  };

  explicit PosedScene(RTCScene scene) : scene_(scene) {}
  void attach(RTCDevice device, Geometry& geometry, unsigned id, const glm::mat4& objectToWorld, unsigned mask);
  SurfaceHit triangleHit(const Geometry& geometry, unsigned primitive, const Ray& ray) const;
  SurfaceHit analyticHit(const Geometry& geometry, unsigned id, const Ray& ray, const Departure* departure) const;
  SurfaceHit patchHit(const Geometry& geometry, unsigned id, unsigned piece, const Ray& ray,
                      const Departure* departure) const;

  RTCScene scene_;
  std::vector<Geometry> geometries_;                          // indexed by Embree geometry ID
  std::vector<std::unique_ptr<scene::Mesh>> deformedMeshes_;  // this pose's shapes of deforming meshes
};

}  // namespace specula::reference
