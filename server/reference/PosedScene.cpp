#include "reference/PosedScene.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <type_traits>

#include "math/Transform.h"
#include "reference/EmbreeError.h"
#include "scene/Deformation.h"

namespace specula::reference {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Embree's context, extended with what the analytic intersector needs to know about the ray.
struct TraceContext {
  RTCIntersectContext embree;  // first member: Embree hands callbacks a pointer to it
  const Departure* departure;
};
static_assert(std::is_standard_layout_v<TraceContext>);

// The one rule for where a ray meets an analytic surface, used while Embree traverses and afterwards.
std::optional<double> analyticT(const AnalyticSurface& surface, unsigned id, const Ray& ray, double tMax,
                                const Departure* departure) {
  const glm::dvec3 origin(ray.origin), direction(ray.direction);
  if (departure && departure->geometry == id)
    return surface.intersectLeaving(departure->exit, origin, direction, 0.0, tMax);
  return surface.intersect(origin, direction, 0.0, tMax);
}

// The one rule for where a ray meets a piece of a parametric surface: a ray that left the surface
// ignores hits within the surface's self-hit distance of its start.
std::optional<PatchSurfaceHit> patchT(const PatchSurface& surface, unsigned id, unsigned piece, const Ray& ray,
                                      double tMax, const Departure* departure) {
  const double tMin = departure && departure->geometry == id ? surface.selfHitDistance() : 0.0;
  return surface.intersectPiece(piece, glm::dvec3(ray.origin), glm::dvec3(ray.direction), tMin, tMax);
}

// Rounded outwards so the float box still contains the double surface.
RTCBounds outwardBounds(const glm::dvec3& low, const glm::dvec3& high) {
  const auto down = [](double x) { return std::nextafter(static_cast<float>(x), -kInfinity); };
  const auto up = [](double x) { return std::nextafter(static_cast<float>(x), kInfinity); };
  return RTCBounds{down(low.x), down(low.y), down(low.z), 0.0f, up(high.x), up(high.y), up(high.z), 0.0f};
}

Ray rayOf(const RTCRayHit& rayHit) {
  return Ray{{rayHit.ray.org_x, rayHit.ray.org_y, rayHit.ray.org_z},
             {rayHit.ray.dir_x, rayHit.ray.dir_y, rayHit.ray.dir_z}};
}

void patchBounds(const RTCBoundsFunctionArguments* args) {
  const auto [low, high] = static_cast<const PatchSurface*>(args->geometryUserPtr)->pieceBounds(args->primID);
  *args->bounds_o = outwardBounds(low, high);
}

void patchIntersect(const RTCIntersectFunctionNArguments* args) {
  assert(args->N == 1);  // rtcIntersect1 is the only query
  if (args->valid[0] == 0) return;
  RTCRayHit& rayHit = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  const auto* context = reinterpret_cast<const TraceContext*>(args->context);
  const auto hit = patchT(*static_cast<const PatchSurface*>(args->geometryUserPtr), args->geomID, args->primID,
                          rayOf(rayHit), rayHit.ray.tfar, context->departure);
  if (!hit) return;
  rayHit.ray.tfar = static_cast<float>(hit->t);
  rayHit.hit.geomID = args->geomID;
  rayHit.hit.primID = args->primID;
  rayHit.hit.instID[0] = args->context->instID[0];
}

void analyticBounds(const RTCBoundsFunctionArguments* args) {
  const auto [low, high] = static_cast<const AnalyticSurface*>(args->geometryUserPtr)->bounds();
  *args->bounds_o = outwardBounds(low, high);
}

void analyticIntersect(const RTCIntersectFunctionNArguments* args) {
  assert(args->N == 1);  // rtcIntersect1 is the only query
  if (args->valid[0] == 0) return;
  RTCRayHit& rayHit = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  const auto* context = reinterpret_cast<const TraceContext*>(args->context);
  const auto t = analyticT(*static_cast<const AnalyticSurface*>(args->geometryUserPtr), args->geomID, rayOf(rayHit),
                           rayHit.ray.tfar, context->departure);
  if (!t) return;
  rayHit.ray.tfar = static_cast<float>(*t);
  rayHit.hit.geomID = args->geomID;
  rayHit.hit.primID = args->primID;
  rayHit.hit.instID[0] = args->context->instID[0];
}

}  // namespace

PosedScene::~PosedScene() { rtcReleaseScene(scene_); }

Result<std::unique_ptr<PosedScene>> PosedScene::build(RTCDevice device, const scene::Scene& scene,
                                                      const scene::ScenePose& pose) {
  assert(pose.objectToWorld.size() == scene.objects.size());
  const RTCScene embreeScene = rtcNewScene(device);
  if (auto failure = embreeFailure(device, "create a scene")) return *failure;
  std::unique_ptr<PosedScene> posed(new PosedScene(embreeScene));
  // A reference favours exactness over speed: no traversal shortcuts that lose precision.
  rtcSetSceneFlags(embreeScene, RTC_SCENE_FLAG_ROBUST);

  // Every record exists before any is attached: analytic geometries keep pointers into them.
  for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
    const scene::SceneObject& object = scene.objects[i];
    Geometry geometry{
        i, std::nullopt, nullptr, &scene.meshes[object.mesh], nullptr, math::normalMatrix(pose.objectToWorld[i])};
    const std::span<const float> weights =
        i < pose.morphWeights.size() ? std::span<const float>(pose.morphWeights[i]) : std::span<const float>();
    const std::span<const glm::mat4> joints = i < pose.jointMatrices.size()
                                                  ? std::span<const glm::mat4>(pose.jointMatrices[i])
                                                  : std::span<const glm::mat4>();
    if (!weights.empty() || !joints.empty()) {
      auto deformed = std::make_unique<scene::Mesh>();
      deformed->name = geometry.mesh->name;
      deformed->vertices = scene::deformedVertices(*geometry.mesh, weights, joints);
      deformed->indices = geometry.mesh->indices;
      geometry.mesh = posed->deformedMeshes_.emplace_back(std::move(deformed)).get();
    }
    // An open mirror's shape would also cover where the mesh has no surface, so only closed ones use it.
    if (object.mirror && object.mirror->exactQuadric())
      geometry.analytic.emplace(*object.mirror->analytic, pose.objectToWorld[i]);
    else if (!geometry.mesh->patches.empty())
      geometry.patches = std::make_shared<PatchSurface>(geometry.mesh->patches, pose.objectToWorld[i]);
    else if (geometry.mesh->triangleCount() == 0) continue;
    posed->geometries_.push_back(geometry);
  }
  for (unsigned id = 0; id < posed->geometries_.size(); ++id) {
    Geometry& geometry = posed->geometries_[id];
    const scene::SceneObject& object = scene.objects[geometry.object];
    const unsigned mask = kSeenDirectly | (object.reflected ? kSeenInMirrors : 0u);
    posed->attach(device, geometry, id, pose.objectToWorld[geometry.object], mask);
    if (auto failure = embreeFailure(device, "add object '" + object.name + "'")) return *failure;
  }
  rtcCommitScene(embreeScene);
  if (auto failure = embreeFailure(device, "build the ray-tracing hierarchy of scene '" + scene.name + "'"))
    return *failure;
  return posed;
}

void PosedScene::attach(RTCDevice device, Geometry& geometry, unsigned id, const glm::mat4& objectToWorld,
                        unsigned mask) {
  RTCGeometry handle = nullptr;
  if (geometry.analytic) {
    handle = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(handle, 1);
    rtcSetGeometryUserData(handle, &*geometry.analytic);
    rtcSetGeometryBoundsFunction(handle, analyticBounds, nullptr);
    rtcSetGeometryIntersectFunction(handle, analyticIntersect);
  } else if (geometry.patches) {
    handle = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(handle, static_cast<unsigned>(geometry.patches->pieceCount()));
    rtcSetGeometryUserData(handle, const_cast<PatchSurface*>(geometry.patches.get()));
    rtcSetGeometryBoundsFunction(handle, patchBounds, nullptr);
    rtcSetGeometryIntersectFunction(handle, patchIntersect);
  } else {
    const scene::Mesh& mesh = *geometry.mesh;
    handle = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    auto* positions = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
        handle, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), mesh.vertices.size()));
    if (positions) {
      // Transformed in double and rounded once, so vertices are as exact as floats allow.
      const glm::dmat4 toWorld(objectToWorld);
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        positions[v] = glm::vec3(toWorld * glm::dvec4(glm::dvec3(mesh.vertices[v].position), 1.0));
    }
    geometry.worldPositions = positions;
    rtcSetSharedGeometryBuffer(handle, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                               3 * sizeof(std::uint32_t), mesh.triangleCount());
  }
  rtcSetGeometryMask(handle, mask);
  rtcCommitGeometry(handle);
  rtcAttachGeometryByID(scene_, handle, id);
  rtcReleaseGeometry(handle);  // the scene holds it now
}

std::optional<SurfaceHit> PosedScene::intersect(const Ray& ray, unsigned mask, const Departure* departure) const {
  TraceContext context{{}, departure};
  rtcInitIntersectContext(&context.embree);
  RTCRayHit rayHit{};
  rayHit.ray.org_x = ray.origin.x;
  rayHit.ray.org_y = ray.origin.y;
  rayHit.ray.org_z = ray.origin.z;
  rayHit.ray.dir_x = ray.direction.x;
  rayHit.ray.dir_y = ray.direction.y;
  rayHit.ray.dir_z = ray.direction.z;
  rayHit.ray.tnear = 0.0f;
  rayHit.ray.tfar = kInfinity;
  rayHit.ray.mask = mask;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context.embree, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const Geometry& geometry = geometries_[rayHit.hit.geomID];
  if (geometry.analytic) return analyticHit(geometry, rayHit.hit.geomID, ray, departure);
  if (geometry.patches) return patchHit(geometry, rayHit.hit.geomID, rayHit.hit.primID, ray, departure);
  return triangleHit(geometry, rayHit.hit.primID, ray);
}

SurfaceHit PosedScene::triangleHit(const Geometry& geometry, unsigned primitive, const Ray& ray) const {
  const std::uint32_t* corner = &geometry.mesh->indices[3 * static_cast<std::size_t>(primitive)];
  const glm::dvec3 a(geometry.worldPositions[corner[0]]), b(geometry.worldPositions[corner[1]]),
      c(geometry.worldPositions[corner[2]]);
  // Embree found the triangle; its barycentrics are redone in double (Möller–Trumbore) for the exact
  // hit, which is then taken from the barycentrics rather than the ray (Wächter & Binder).
  const glm::dvec3 origin(ray.origin), direction(ray.direction);
  const glm::dvec3 edge1 = b - a, edge2 = c - a, p = glm::cross(direction, edge2), s = origin - a;
  const double inverse = 1.0 / glm::dot(edge1, p);
  const double u = glm::dot(s, p) * inverse, v = glm::dot(direction, glm::cross(s, edge1)) * inverse, w = 1.0 - u - v;

  const scene::Vertex& va = geometry.mesh->vertices[corner[0]];
  const scene::Vertex& vb = geometry.mesh->vertices[corner[1]];
  const scene::Vertex& vc = geometry.mesh->vertices[corner[2]];
  SurfaceHit hit;
  hit.object = geometry.object;
  hit.position = a + u * edge1 + v * edge2;
  hit.geometricNormal = glm::normalize(glm::cross(edge1, edge2));
  const glm::dvec3 normal = w * glm::dvec3(va.normal) + u * glm::dvec3(vb.normal) + v * glm::dvec3(vc.normal);
  hit.shadingNormal = glm::dmat3(geometry.normalToWorld) * normal;
  hit.uv = glm::vec2(w * glm::dvec2(va.uv) + u * glm::dvec2(vb.uv) + v * glm::dvec2(vc.uv));
  // shading.glsl's uvPerMetre: the root of the triangle's area ratio, uv over world.
  const glm::dvec2 uvEdge1 = glm::dvec2(vb.uv) - glm::dvec2(va.uv), uvEdge2 = glm::dvec2(vc.uv) - glm::dvec2(va.uv);
  const double area = glm::length(glm::cross(edge1, edge2));
  hit.uvPerMetre =
      area > 0.0 ? static_cast<float>(std::sqrt(std::abs(uvEdge1.x * uvEdge2.y - uvEdge1.y * uvEdge2.x) / area)) : 0.0f;
  return hit;
}

SurfaceHit PosedScene::analyticHit(const Geometry& geometry, unsigned id, const Ray& ray,
                                   const Departure* departure) const {
  const AnalyticSurface& surface = *geometry.analytic;
  // Embree kept only a float distance; the same rule gives the double one (it was the nearest root).
  const std::optional<double> t = analyticT(surface, id, ray, std::numeric_limits<double>::infinity(), departure);
  assert(t);
  SurfaceHit hit;
  hit.object = geometry.object;
  hit.position = surface.surfacePoint(glm::dvec3(ray.origin), glm::dvec3(ray.direction), *t);
  hit.geometricNormal = surface.outwardNormal(hit.position);
  hit.shadingNormal = hit.geometricNormal;
  hit.uv = surface.uv(hit.position);
  hit.analyticGeometry = id;
  return hit;
}

SurfaceHit PosedScene::patchHit(const Geometry& geometry, unsigned id, unsigned piece, const Ray& ray,
                                const Departure* departure) const {
  // Embree kept only a float distance; the same rule on the same piece gives the double hit.
  const auto found = patchT(*geometry.patches, id, piece, ray, std::numeric_limits<double>::infinity(), departure);
  assert(found);
  const math::PatchSample sample = geometry.patches->sample(*found);
  SurfaceHit hit;
  hit.object = geometry.object;
  hit.position = sample.position;
  hit.geometricNormal = sample.normal;
  hit.shadingNormal = sample.normal;
  hit.uv = glm::vec2(found->uv);
  hit.analyticGeometry = id;
  return hit;
}

}  // namespace specula::reference
