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

ReflectionPointErrors measureReflectionPoints(const render::Renderer& renderer, const scene::ScenePose& pose,
                                              const render::RenderedFrame& frame, double marginPixels) {
  ReflectionPointErrors errors;
  const std::vector<passes::ReflectedVertex> results = renderer.readReflectedVertices();
  const scene::Scene& scene = renderer.scene();
  const glm::dvec3 eye(pose.camera.eye);
  for (const passes::MirrorSlots& mirror : renderer.reflectionSlots().mirrors) {
    // Mirrors not drawn this frame still hold an older frame's results.
    if (std::find(frame.drawnMirrors.begin(), frame.drawnMirrors.end(), mirror.mirrorObject) == frame.drawnMirrors.end()) continue;
    const scene::SceneObject& mirrorObject = scene.objects[mirror.mirrorObject];
    if (!isAnalyticSphere(mirrorObject)) continue;
    const auto sphere = worldSphere(*mirrorObject.mirror->analytic, pose.objectToWorld[mirror.mirrorObject]);
    if (!sphere) continue;
    for (const passes::ReflectionSlotRange& range : mirror.reflected) {
      const scene::Mesh& mesh = scene.meshes[scene.objects[range.object].mesh];
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const std::size_t slot = range.firstSlot + v;
        const passes::ReflectedVertex& result = results[slot];
        const glm::dvec3 vertex(pose.objectToWorld[range.object] * glm::vec4(mesh.vertices[v].position, 1.0f));
        const auto exact = math::sphereReflectionPoint(*sphere, eye, vertex);
        const bool searchVisible = (result.state.w & (passes::ReflectedVertex::kHidden | passes::ReflectedVertex::kUnsolved)) == 0;
        if (!exact) {
          errors.exactHiddenButSearchVisible += searchVisible;
          continue;
        }
        if ((frame.view.worldToClip() * glm::vec4(glm::vec3(*exact), 1.0f)).w <= 0.0f) continue;  // behind the eye
        const glm::dvec2 exactPixel = toPixels(frame.view, glm::vec3(*exact), frame.width, frame.height);
        if (exactPixel.x < -marginPixels || exactPixel.y < -marginPixels || exactPixel.x > frame.width + marginPixels ||
            exactPixel.y > frame.height + marginPixels)
          continue;
        if (!searchVisible) {
          errors.searchHiddenButExactVisible++;
          continue;
        }
        const glm::dvec2 offset = toPixels(frame.view, glm::vec3(result.reflectionPoint), frame.width, frame.height) - exactPixel;
        errors.pixels.push_back(glm::length(offset));
        errors.vertices.push_back({slot, exactPixel, offset});
      }
    }
  }
  return errors;
}

}  // namespace specula::bench
