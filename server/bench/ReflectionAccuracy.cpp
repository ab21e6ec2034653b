#include "bench/ReflectionAccuracy.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "math/SphereReflection.h"

namespace specula::bench {

namespace {

bool isAnalyticSphere(const scene::SceneObject& object) {
  return object.mirror && object.mirror->analytic && object.mirror->analytic->kind == scene::AnalyticShape::Kind::Sphere;
}

// The mirror's sphere in world space; nullopt when its transform does not keep it a sphere.
std::optional<math::Sphere> worldSphere(const scene::AnalyticShape& shape, const glm::mat4& objectToWorld) {
  const glm::dvec3 scale(glm::length(glm::vec3(objectToWorld[0])), glm::length(glm::vec3(objectToWorld[1])),
                         glm::length(glm::vec3(objectToWorld[2])));
  if (std::abs(scale.x - scale.y) > 1e-5 * scale.x || std::abs(scale.x - scale.z) > 1e-5 * scale.x) return std::nullopt;
  return math::Sphere{glm::dvec3(objectToWorld * glm::vec4(shape.center, 1.0f)), shape.radii.x * scale.x};
}

}  // namespace

glm::dvec2 toPixels(const passes::FrameView& view, const glm::vec3& world, int width, int height) {
  const glm::vec4 clip = view.worldToClip() * glm::vec4(world, 1.0f);
  const glm::dvec2 ndc = glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w);
  return {(ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
}

double ReflectionPointErrors::percentile(double p) const {
  if (pixels.empty()) return 0.0;
  std::vector<double> sorted = pixels;
  std::sort(sorted.begin(), sorted.end());
  const double rank = std::ceil(p * static_cast<double>(sorted.size()));  // nearest-rank definition
  return sorted[std::clamp(static_cast<std::size_t>(std::max(rank, 1.0)) - 1, std::size_t{0}, sorted.size() - 1)];
}

double ReflectionPointErrors::mean() const {
  return pixels.empty() ? 0.0 : std::accumulate(pixels.begin(), pixels.end(), 0.0) / static_cast<double>(pixels.size());
}

bool hasAnalyticSphereMirror(const scene::Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(), isAnalyticSphere);
}

namespace {

// Judges one search result against the exact sphere solver and adds it to `errors`.
void judge(ReflectionPointErrors& errors, const render::RenderedFrame& frame, const math::Sphere& sphere, const glm::dvec3& eye,
           const glm::dvec3& vertex, const glm::vec3& reflectionPoint, int flags, std::size_t slot, double marginPixels) {
  // A point on or inside the mirror (a tessellated edge through it) has no reflection to judge.
  if (glm::length(vertex - sphere.center) <= sphere.radius) return;
  const auto exact = math::sphereReflectionPoint(sphere, eye, vertex);
  const bool searchVisible = (flags & (passes::ReflectedVertex::kHidden | passes::ReflectedVertex::kUnsolved)) == 0;
  if (!exact) {
    errors.exactHiddenButSearchVisible += searchVisible;
    return;
  }
  if ((frame.view.worldToClip() * glm::vec4(glm::vec3(*exact), 1.0f)).w <= 0.0f) return;  // behind the eye
  const glm::dvec2 exactPixel = toPixels(frame.view, glm::vec3(*exact), frame.width, frame.height);
  if (exactPixel.x < -marginPixels || exactPixel.y < -marginPixels || exactPixel.x > frame.width + marginPixels ||
      exactPixel.y > frame.height + marginPixels)
    return;
  if (!searchVisible) {
    errors.searchHiddenButExactVisible++;
    const double grazing = glm::dot(glm::normalize(eye - *exact), glm::normalize(*exact - sphere.center));
    errors.searchHiddenNearSilhouette += grazing < ReflectionPointErrors::kNearSilhouetteCosine;
    return;
  }
  const glm::dvec2 offset = toPixels(frame.view, reflectionPoint, frame.width, frame.height) - exactPixel;
  errors.pixels.push_back(glm::length(offset));
  errors.vertices.push_back({slot, exactPixel, offset});
}

// The world sphere of a mirror drawn this frame with an analytic sphere; nullopt otherwise.
std::optional<math::Sphere> measuredSphere(const scene::Scene& scene, const scene::ScenePose& pose,
                                           const render::RenderedFrame& frame, std::size_t mirror) {
  // Mirrors not drawn this frame still hold an older frame's results.
  if (std::find(frame.drawnMirrors.begin(), frame.drawnMirrors.end(), mirror) == frame.drawnMirrors.end()) return std::nullopt;
  const scene::SceneObject& mirrorObject = scene.objects[mirror];
  if (!isAnalyticSphere(mirrorObject)) return std::nullopt;
  return worldSphere(*mirrorObject.mirror->analytic, pose.objectToWorld[mirror]);
}

}  // namespace

ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                              const render::RenderedFrame& frame, double marginPixels) {
  ReflectionPointErrors errors;
  const std::vector<passes::ReflectedVertex> results = renderer.readReflectedVertices();
  const scene::Scene& scene = renderer.scene();
  const glm::dvec3 eye(pose.camera.eye);
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    const auto sphere = measuredSphere(scene, pose, frame, mirror.mirrorObject);
    if (!sphere) continue;
    for (const passes::ReflectionSlotRange& range : mirror.reflected) {
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const std::size_t slot = range.firstSlot + v;
        const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
        judge(errors, frame, *sphere, eye, vertex, glm::vec3(results[slot].reflectionPoint), results[slot].state.w, slot,
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
    const auto sphere = measuredSphere(renderer.scene(), pose, frame, finished[i].mirrorObject);
    if (!sphere) continue;
    const passes::TessellatedVertex& record = finished[i].record;
    judge(errors, frame, *sphere, eye, glm::dvec3(record.positionU), glm::vec3(record.reflectionTexelX),
          static_cast<int>(record.virtualFlags.w), i, marginPixels);
  }
  return errors;
}

}  // namespace specula::bench
