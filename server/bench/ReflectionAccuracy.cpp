#include "bench/ReflectionAccuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <memory>
#include <variant>

#include "math/ExtrusionReflection.h"
#include "math/PatchReflection.h"
#include "math/SphereReflection.h"

namespace specula::bench {

namespace {

bool isAnalyticSphere(const scene::SceneObject& object) {
  return object.mirror && object.mirror->analytic && object.mirror->analytic->kind == scene::AnalyticShape::Kind::Sphere;
}

bool hasExactShape(const scene::SceneObject& object, const scene::Scene& scene) {
  return isAnalyticSphere(object) || (object.mirror && object.mirror->extrusion) ||
         (object.mirror && !scene.meshes[object.mesh].patches.empty());
}

// The exact answer for one mirror in world space: its analytic sphere, its declared extrusion or its
// Bézier patches.
struct ExactMirror {
  std::variant<math::Sphere, math::Extrusion, std::shared_ptr<const math::PatchReflectionSolver>> shape;
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
    return glm::length(glm::dvec2(glm::dot(offset, extrusion.u), glm::dot(offset, extrusion.v)) / extrusion.radii) <= kOnSurface;
  }

  // A surface of patches may reflect a vertex at several points: the one nearest `searched` is judged.
  std::optional<math::SurfacePoint> reflection(const glm::dvec3& eye, const glm::dvec3& vertex,
                                               const glm::dvec3& searched) const {
    if (const auto* solver = std::get_if<std::shared_ptr<const math::PatchReflectionSolver>>(&shape)) {
      std::vector<math::PatchPoint> points = (*solver)->solve(eye, vertex);
      // Newton's method in double precision from by the searched point finds a solution there if
      // there is one, even one the grid's starts missed; the search's own answer is not trusted.
      if (const auto local = (*solver)->solveNear(eye, vertex, searched)) points.push_back(*local);
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
std::optional<ExactMirror> worldShape(const scene::MirrorInfo& mirror, const scene::Mesh& mesh, const glm::mat4& objectToWorld) {
  if (!mesh.patches.empty()) {
    std::vector<math::BezierPatch> world;
    for (const math::BezierPatch& patch : mesh.patches) world.push_back(patch.transformed(glm::dmat4(objectToWorld)));
    return ExactMirror{std::make_shared<const math::PatchReflectionSolver>(std::move(world))};
  }
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

double nearestRankPercentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(p * static_cast<double>(values.size()));
  return values[std::clamp(static_cast<std::size_t>(std::max(rank, 1.0)) - 1, std::size_t{0}, values.size() - 1)];
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
void judge(ReflectionPointErrors& errors, const render::RenderedFrame& frame, const ExactMirror& mirror, const glm::dvec3& eye,
           const glm::dvec3& vertex, const glm::vec3& reflectionPoint, int flags, std::size_t slot, double marginPixels) {
  if (mirror.encloses(vertex)) return;
  const std::optional<math::SurfacePoint> solved = mirror.reflection(eye, vertex, glm::dvec3(reflectionPoint));
  const std::optional<glm::dvec3> exact = solved ? std::optional(solved->position) : std::nullopt;
  const bool searchVisible = (flags & (passes::ReflectedVertex::kHidden | passes::ReflectedVertex::kUnsolved)) == 0;
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

// The world shape of a mirror drawn this frame with an analytic sphere or an extrusion; nullopt otherwise.
std::optional<ExactMirror> measuredShape(const scene::Scene& scene, const scene::ScenePose& pose,
                                           const render::RenderedFrame& frame, std::size_t mirror) {
  // Mirrors not drawn this frame still hold an older frame's results.
  if (std::find(frame.drawnMirrors.begin(), frame.drawnMirrors.end(), mirror) == frame.drawnMirrors.end()) return std::nullopt;
  const scene::SceneObject& mirrorObject = scene.objects[mirror];
  if (!hasExactShape(mirrorObject, scene)) return std::nullopt;
  return worldShape(*mirrorObject.mirror, scene.meshes[mirrorObject.mesh], pose.objectToWorld[mirror]);
}

}  // namespace

ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                              const render::RenderedFrame& frame, double marginPixels) {
  ReflectionPointErrors errors;
  const std::vector<passes::ReflectedVertex> results = renderer.readReflectedVertices();
  const scene::Scene& scene = renderer.scene();
  const glm::dvec3 eye(pose.camera.eye);
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    const auto shape = measuredShape(scene, pose, frame, mirror.mirrorObject);
    if (!shape) continue;
    const bool patches = std::holds_alternative<std::shared_ptr<const math::PatchReflectionSolver>>(shape->shape);
    for (const passes::ReflectionSlotRange& range : mirror.reflected) {
      // A vertex on the patches themselves is its own reflection point: nothing to judge.
      if (patches && range.object == mirror.mirrorObject) continue;
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const std::size_t slot = range.firstSlot + v;
        const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
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
  for (std::size_t i = 0; i < finished.size(); ++i) {
    const auto shape = measuredShape(renderer.scene(), pose, frame, finished[i].mirrorObject);
    if (!shape) continue;
    const passes::TessellatedVertex& record = finished[i].record;
    judge(errors, frame, *shape, eye, glm::dvec3(record.positionU), glm::vec3(record.reflectionTexelX),
          static_cast<int>(record.virtualFlags.w), i, marginPixels);
  }
  return errors;
}

}  // namespace specula::bench
