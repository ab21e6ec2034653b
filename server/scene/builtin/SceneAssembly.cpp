#include "scene/builtin/SceneAssembly.h"

#include <cassert>
#include <cmath>
#include <utility>

#include "math/Color.h"

namespace specula::scene::builtin {

glm::vec3 srgbHex(std::uint32_t rgb) {
  const auto channel = [rgb](int shift) { return static_cast<float>((rgb >> shift) & 0xFFu) / 255.0f; };
  return math::srgbToLinear(glm::vec3(channel(16), channel(8), channel(0)));
}

Material matte(std::string name, std::uint32_t rgb) {
  Material m;
  m.name = std::move(name);
  m.baseColor = srgbHex(rgb);
  return m;
}

Material emissive(std::string name, std::uint32_t rgb) {
  Material m = matte(std::move(name), rgb);
  m.unlit = true;
  return m;
}

Material mirror(std::string name, std::uint32_t rgb, float reflectivity) {
  Material m = matte(std::move(name), rgb);
  m.reflectivity = reflectivity;
  return m;
}

Material checker(std::string name, std::uint32_t even, std::uint32_t odd, float cellsPerUnit, bool unlit) {
  Material m = matte(std::move(name), even);
  m.unlit = unlit;
  m.checker = Checker{srgbHex(odd), cellsPerUnit};
  return m;
}

Material perfectMirror(std::string name) {
  Material m = mirror(std::move(name), 0x000000, 1.0f);
  m.unlit = true;
  return m;
}

std::vector<glm::vec2> ellipseArc(const glm::vec2& centre, const glm::vec2& radii, float fromDegrees, float toDegrees,
                                  int count) {
  assert(count >= 2);
  std::vector<glm::vec2> points;
  for (int k = 0; k < count; ++k) {
    const float t = static_cast<float>(k) / static_cast<float>(count - 1);
    const float a = glm::radians(fromDegrees + (toDegrees - fromDegrees) * t);
    points.push_back(centre + radii * glm::vec2(std::cos(a), std::sin(a)));
  }
  return points;
}

glm::quat yaw(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f)); }

math::Transform placed(const glm::vec3& translation, float yawDegrees, const glm::vec3& scale) {
  return {translation, yaw(yawDegrees), scale};
}

Light sunLight(const glm::vec3& towardsLight, float intensity) {
  return {Light::Kind::Directional, glm::normalize(towardsLight), glm::vec3(1.0f), intensity};
}

std::uint32_t addMesh(Scene& scene, Mesh mesh) {
  scene.meshes.push_back(std::move(mesh));
  return static_cast<std::uint32_t>(scene.meshes.size() - 1);
}

std::uint32_t addMaterial(Scene& scene, Material material) {
  scene.materials.push_back(std::move(material));
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

std::uint32_t addObject(Scene& scene, std::string name, std::uint32_t mesh, std::uint32_t material,
                        const math::Transform& transform) {
  SceneObject object;
  object.name = std::move(name);
  object.mesh = mesh;
  object.material = material;
  object.transform = transform;
  scene.objects.push_back(std::move(object));
  return static_cast<std::uint32_t>(scene.objects.size() - 1);
}

std::uint32_t addSphereMirror(Scene& scene, std::string name, std::uint32_t mesh, std::uint32_t material, float radius,
                              const math::Transform& transform) {
  const std::uint32_t object = addObject(scene, std::move(name), mesh, material, transform);
  MirrorInfo& info = scene.objects[object].mirror.emplace();
  info.curvature = MirrorCurvature::Convex;
  info.closed = true;
  info.analytic = AnalyticShape{AnalyticShape::Kind::Sphere, glm::vec3(0.0f), glm::vec3(radius)};
  return object;
}

}  // namespace specula::scene::builtin
