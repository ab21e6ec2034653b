#include "bench/ReflectionAccuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <memory>
#include <variant>

#include "base/Percentile.h"
#include "math/ExtrusionReflection.h"
#include "math/PatchReflection.h"
#include "math/SphereReflection.h"
#include "reference/PatchSurface.h"
#include "scene/Deformation.h"

namespace specula::bench {

namespace {

bool isAnalyticSphere(const scene::SceneObject& object) {
  return object.mirror && object.mirror->analytic &&
         object.mirror->analytic->kind == scene::AnalyticShape::Kind::Sphere;
}

bool hasExactShape(const scene::SceneObject& object, const scene::Scene& scene) {
  return isAnalyticSphere(object) || (object.mirror && object.mirror->extrusion) ||
         (object.mirror && !scene.meshes[object.mesh].patches.empty());
}

// One part of a parametric mirror in world space: the whole mirror's solver and surface, and what
// decides whether a solution counts. For a vertex the search hid, only a reflection the part shows:
// one that lies in the part (the grid triangle its (u, v) falls in, as the G-buffer assigns texels)
// and that the eye sees past the whole mirror (the part's layer shows only texels no other part
// covers). Judged against every reflection instead, a vertex rightly hidden in one part was counted
// as missed for its reflection in another, or behind the spout. A point the search calls visible is
// judged by where it lies, against all of them: at an occluding edge or a boundary between parts
// the texel it was accepted by and the exact point can disagree within a pixel.
struct PatchPart {
  std::shared_ptr<const math::PatchReflectionSolver> solver;  // the whole mirror, world space
  std::shared_ptr<const reference::PatchSurface> surface;     // the same, for occlusion
  const std::vector<std::uint8_t>* triangleParts = nullptr;   // null: one part
  int part = 0, segments = 1;

  bool counts(const glm::dvec3& eye, const math::PatchPoint& point, bool searchHid) const {
    return !searchHid || (inPart(point) && !occluded(eye, point.position));
  }

 private:
  bool inPart(const math::PatchPoint& point) const {
    if (!triangleParts) return true;
    const std::size_t triangle = math::patchGridTriangle(point.patch, point.uv, segments);
    return triangle < triangleParts->size() && (*triangleParts)[triangle] == part;
  }

  // Whether the mirror meets the eye's ray to `point` before it. Not within a margin of it: a ray
  // grazing the surface at `point` meets it there as a double root, which Newton's method places
  // only to the square root of its tolerance along the ray.
  bool occluded(const glm::dvec3& eye, const glm::dvec3& point) const {
    const glm::dvec3 direction = point - eye;
    return surface->meetsBefore(eye, direction, 1.0 - 100.0 * surface->selfHitDistance() / glm::length(direction));
  }
};

// The exact answer for one mirror (part) in world space: its analytic sphere, its declared extrusion
// or its Bézier patches.
struct ExactMirror {
  std::variant<math::Sphere, math::Extrusion, PatchPart> shape;
  // An extrusion is unbounded; the mirror spans these heights along it (its mesh's): a reflection
  // point beyond them lies on no mirror, so whatever the search made of it is not judged.
  glm::dvec2 heights{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};

  // On or inside the surface (a tessellated edge through it, an object's float vertex resting on
  // it): no reflection to judge.
  bool encloses(const glm::dvec3& point) const {
    constexpr double kOnSurface = 1.0 + 1e-5;  // of the radius: float rounding of a vertex placed on it
    if (const auto* sphere = std::get_if<math::Sphere>(&shape))
      return glm::length(point - sphere->center) <= kOnSurface * sphere->radius;
    if (!std::holds_alternative<math::Extrusion>(shape)) return false;  // patches: their own vertices are skipped
    const auto& extrusion = std::get<math::Extrusion>(shape);
    const glm::dvec3 offset = point - extrusion.axisPoint;
    return glm::length(glm::dvec2(glm::dot(offset, extrusion.u), glm::dot(offset, extrusion.v)) / extrusion.radii) <=
           kOnSurface;
  }

  // A surface of patches may reflect a vertex at several points: the one nearest `searched` of those
  // that count (PatchPart) is judged.
  std::optional<math::SurfacePoint> reflection(const glm::dvec3& eye, const glm::dvec3& vertex,
                                               const glm::dvec3& searched, bool searchHid) const {
    if (const auto* patches = std::get_if<PatchPart>(&shape)) {
      std::vector<math::PatchPoint> points = patches->solver->solve(eye, vertex);
      // Newton's method in double precision from by the searched point finds a solution there if
      // there is one, even one the grid's starts missed; the search's own answer is not trusted.
      if (const auto local = patches->solver->solveNear(eye, vertex, searched)) points.push_back(*local);
      std::erase_if(points, [&](const math::PatchPoint& point) { return !patches->counts(eye, point, searchHid); });
      if (points.empty()) return std::nullopt;
      const auto nearest = std::min_element(points.begin(), points.end(), [&](const auto& a, const auto& b) {
        return glm::length(a.position - searched) < glm::length(b.position - searched);
      });
      return math::SurfacePoint{nearest->position, nearest->normal, 0.0};
    }
    if (const auto* sphere = std::get_if<math::Sphere>(&shape)) {
      const auto point = math::sphereReflectionPoint(*sphere, eye, vertex);
      if (!point) return std::nullopt;
      return math::SurfacePoint{*point, glm::normalize(*point - sphere->center), 0.0};
    }
    return math::extrusionReflectionPoint(std::get<math::Extrusion>(shape), eye, vertex);
  }

  bool beyondTheMirror(const glm::dvec3& point) const {
    const auto* extrusion = std::get_if<math::Extrusion>(&shape);
    if (!extrusion) return false;
    const double height = glm::dot(point - extrusion->axisPoint, extrusion->direction);
    return height < heights.x || height > heights.y;
  }
};

// The mirror's exact shape in world space; nullopt when its transform does not keep a sphere one.
std::optional<ExactMirror> worldShape(const scene::MirrorInfo& mirror, const scene::Mesh& mesh,
                                      const glm::mat4& objectToWorld) {
  if (mirror.extrusion) {
    const auto extrusion = mirror.extrusion->transformed(glm::dmat4(objectToWorld));
    if (!extrusion) return std::nullopt;
    ExactMirror exact{*extrusion};
    exact.heights = glm::dvec2(std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
    for (const scene::Vertex& v : mesh.vertices) {
      const glm::dvec3 world(objectToWorld * glm::vec4(v.position, 1.0f));
      const double height = glm::dot(world - extrusion->axisPoint, extrusion->direction);
      exact.heights = {std::min(exact.heights.x, height), std::max(exact.heights.y, height)};
    }
    return exact;
  }
  const scene::AnalyticShape& shape = *mirror.analytic;
  const glm::dvec3 scale(glm::length(glm::vec3(objectToWorld[0])), glm::length(glm::vec3(objectToWorld[1])),
                         glm::length(glm::vec3(objectToWorld[2])));
  if (std::abs(scale.x - scale.y) > 1e-5 * scale.x || std::abs(scale.x - scale.z) > 1e-5 * scale.x) return std::nullopt;
  return ExactMirror{math::Sphere{glm::dvec3(objectToWorld * glm::vec4(shape.center, 1.0f)), shape.radii.x * scale.x}};
}

}  // namespace

glm::dvec2 toPixels(const passes::FrameView& view, const glm::vec3& world, int width, int height) {
  const glm::vec4 clip = view.worldToClip() * glm::vec4(world, 1.0f);
  const glm::dvec2 ndc = glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w);
  return {(ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
}

double ReflectionPointErrors::percentile(double p) const { return nearestRankPercentile(pixels, p); }

double ReflectionPointErrors::mean() const {
  return pixels.empty() ? 0.0 : std::accumulate(pixels.begin(), pixels.end(), 0.0) / static_cast<double>(pixels.size());
}

bool hasExactMirror(const scene::Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [&](const scene::SceneObject& object) { return hasExactShape(object, scene); });
}

namespace {

// Judges one search result against the exact solver and adds it to `errors`.
void judge(ReflectionPointErrors& errors, const render::RenderedFrame& frame, const ExactMirror& mirror,
           const glm::dvec3& eye, const glm::dvec3& vertex, const glm::vec3& reflectionPoint, int flags,
           std::size_t slot, double marginPixels) {
  if (mirror.encloses(vertex)) return;
  const bool searchVisible = (flags & (passes::ReflectedVertex::kHidden | passes::ReflectedVertex::kUnsolved)) == 0;
  const std::optional<math::SurfacePoint> solved =
      mirror.reflection(eye, vertex, glm::dvec3(reflectionPoint), !searchVisible);
  const std::optional<glm::dvec3> exact = solved ? std::optional(solved->position) : std::nullopt;
  if (!exact) {
    errors.exactHiddenButSearchVisible += searchVisible;
    return;
  }
  if (mirror.beyondTheMirror(*exact)) return;
  if ((frame.view.worldToClip() * glm::vec4(glm::vec3(*exact), 1.0f)).w <= 0.0f) return;  // behind the eye
  const glm::dvec2 exactPixel = toPixels(frame.view, glm::vec3(*exact), frame.width, frame.height);
  if (exactPixel.x < -marginPixels || exactPixel.y < -marginPixels || exactPixel.x > frame.width + marginPixels ||
      exactPixel.y > frame.height + marginPixels)
    return;
  if (!searchVisible) {
    errors.searchHiddenButExactVisible++;
    const double grazing = glm::dot(glm::normalize(eye - *exact), solved->normal);
    errors.searchHiddenNearSilhouette += grazing < ReflectionPointErrors::kNearSilhouetteCosine;
    return;
  }
  const glm::dvec2 offset = toPixels(frame.view, reflectionPoint, frame.width, frame.height) - exactPixel;
  errors.pixels.push_back(glm::length(offset));
  errors.vertices.push_back({slot, exactPixel, offset});
}

// The exact shapes of the mirror parts drawn this frame, each made once: a parametric mirror's parts
// share its whole surface (for occlusion).
class ExactShapes {
 public:
  ExactShapes(const render::Renderer& renderer, const scene::ScenePose& pose, const render::RenderedFrame& frame)
      : renderer_(renderer), pose_(pose), frame_(frame) {}

  // The world shape of part `part` of `mirror` when it was drawn this frame with an analytic
  // sphere, an extrusion or patches; null otherwise.
  const ExactMirror* of(std::size_t mirror, int part) {
    const auto [at, made] = shapes_.try_emplace(std::pair{mirror, part});
    if (made) at->second = make(mirror, part);
    return at->second ? &*at->second : nullptr;
  }

 private:
  std::optional<ExactMirror> make(std::size_t mirror, int part) {
    // Mirrors not drawn this frame still hold an older frame's results.
    if (std::find(frame_.drawnMirrors.begin(), frame_.drawnMirrors.end(), mirror) == frame_.drawnMirrors.end())
      return std::nullopt;
    const scene::Scene& scene = renderer_.scene();
    const scene::SceneObject& object = scene.objects[mirror];
    if (!hasExactShape(object, scene)) return std::nullopt;
    const scene::Mesh& mesh = scene.meshes[object.mesh];
    const glm::mat4& objectToWorld = pose_.objectToWorld[mirror];
    if (mesh.patches.empty()) return worldShape(*object.mirror, mesh, objectToWorld);
    PatchPart patches = wholeSurfaces_[mirror];
    if (!patches.solver) {
      std::vector<math::BezierPatch> world;
      for (const math::BezierPatch& patch : mesh.patches) world.push_back(patch.transformed(glm::dmat4(objectToWorld)));
      patches.solver = std::make_shared<const math::PatchReflectionSolver>(std::move(world));
      patches.surface = std::make_shared<const reference::PatchSurface>(mesh.patches, objectToWorld);
      wholeSurfaces_[mirror] = patches;
    }
    const auto& parts = renderer_.reflectionSlots().parts;
    const auto split = parts.find(mirror);
    if (split != parts.end() && split->second.parts.size() > 1 &&
        split->second.triangleParts.size() == mesh.triangleCount()) {
      patches.triangleParts = &split->second.triangleParts;
      patches.part = part;
      patches.segments = mesh.patchSegments;
    }
    return ExactMirror{patches};
  }

  const render::Renderer& renderer_;
  const scene::ScenePose& pose_;
  const render::RenderedFrame& frame_;
  std::map<std::pair<std::size_t, int>, std::optional<ExactMirror>> shapes_;
  std::map<std::size_t, PatchPart> wholeSurfaces_;  // a parametric mirror's solver and surface, for all its parts
};

}  // namespace

ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                              const render::RenderedFrame& frame, double marginPixels) {
  ReflectionPointErrors errors;
  const std::vector<passes::ReflectedVertex> results = renderer.readReflectedVertices();
  const scene::Scene& scene = renderer.scene();
  const glm::dvec3 eye(pose.camera.eye);
  ExactShapes shapes(renderer, pose, frame);
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    const ExactMirror* shape = shapes.of(mirror.mirrorObject, mirror.part);
    if (!shape) continue;
    const bool patches = std::holds_alternative<PatchPart>(shape->shape);
    for (const passes::ReflectionSlotRange& range : mirror.reflected) {
      // A vertex on the patches themselves is its own reflection point: nothing to judge.
      if (patches && range.object == mirror.mirrorObject) continue;
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      // A deforming object is searched as the pose shapes it, so it is judged in that shape too.
      std::vector<scene::Vertex> deformed;
      if (scene::deforms(scene, range.object))
        deformed = scene::deformedVertices(mesh, pose.morphWeights[range.object], pose.jointMatrices[range.object]);
      const std::vector<scene::Vertex>& vertices = deformed.empty() ? mesh.vertices : deformed;
      for (std::size_t v = 0; v < vertices.size(); ++v) {
        const std::size_t slot = range.firstSlot + v;
        const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(vertices[v].position, 1.0f));
        judge(errors, frame, *shape, eye, vertex, glm::vec3(results[slot].reflectionPoint), results[slot].state.w, slot,
              marginPixels);
      }
    }
  }
  return errors;
}

ReflectionPointErrors measureTessellatedPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                               const render::RenderedFrame& frame, double marginPixels) {
  ReflectionPointErrors errors;
  const glm::dvec3 eye(pose.camera.eye);
  const std::vector<passes::FinishedVertex> finished = renderer.readTessellatedVertices();
  ExactShapes shapes(renderer, pose, frame);
  for (std::size_t i = 0; i < finished.size(); ++i) {
    const ExactMirror* shape = shapes.of(finished[i].mirrorObject, finished[i].part);
    if (!shape) continue;
    const passes::TessellatedVertex& record = finished[i].record;
    judge(errors, frame, *shape, eye, glm::dvec3(record.positionU), glm::vec3(record.reflectionTexelX),
          static_cast<int>(record.virtualFlags.w), i, marginPixels);
  }
  return errors;
}

}  // namespace specula::bench
