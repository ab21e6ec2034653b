#include "scene/builtin/Tube.h"

#include <cassert>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <utility>
#include <vector>

#include "scene/builtin/SceneAssembly.h"

namespace specula::scene::builtin {

namespace {

// Any unit vector perpendicular to the unit vector t.
glm::vec3 perpendicular(const glm::vec3& t) {
  const glm::vec3 helper = std::abs(t.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  return glm::normalize(glm::cross(helper, t));
}

}  // namespace

Mesh tube(std::string name, std::span<const glm::vec3> path, std::span<const float> radii, int sides) {
  assert(path.size() >= 2 && radii.size() == path.size() && sides >= 3);
  Mesh mesh{std::move(name), {}, {}};
  const std::size_t n = path.size();
  std::vector<float> arc{0.0f};
  for (std::size_t k = 1; k < n; ++k) arc.push_back(arc.back() + glm::distance(path[k - 1], path[k]));

  // Parallel transport keeps the ring frame from twisting along a bending path.
  glm::vec3 normal{0.0f};
  for (std::size_t k = 0; k < n; ++k) {
    const glm::vec3 tangent = glm::normalize(path[std::min(k + 1, n - 1)] - path[k > 0 ? k - 1 : 0]);
    normal = k == 0 ? perpendicular(tangent) : glm::normalize(normal - glm::dot(normal, tangent) * tangent);
    const glm::vec3 binormal = glm::cross(tangent, normal);
    // A tapering tube leans its normals towards the thin end.
    const std::size_t lo = k > 0 ? k - 1 : 0, hi = std::min(k + 1, n - 1);
    const float slope = (radii[hi] - radii[lo]) / (arc[hi] - arc[lo]);
    for (int i = 0; i <= sides; ++i) {
      const float a = glm::two_pi<float>() * static_cast<float>(i % sides) / static_cast<float>(sides);
      const glm::vec3 radial = std::cos(a) * normal + std::sin(a) * binormal;
      mesh.vertices.push_back({path[k] + radii[k] * radial,
                               glm::normalize(radial - slope * tangent),
                               {static_cast<float>(i) / static_cast<float>(sides), arc[k] / arc.back()}});
    }
  }
  // Around × along points outwards because binormal = tangent × normal.
  const auto columns = static_cast<std::uint32_t>(sides + 1);
  for (std::uint32_t k = 0; k + 1 < n; ++k)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(sides); ++i) {
      const std::uint32_t a = k * columns + i, b = a + 1, c = b + columns, d = a + columns;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  return mesh;
}

Mesh arcHandle(std::string name, const glm::vec2& centre, float arcRadius, float fromDegrees, float toDegrees,
               float tubeRadius) {
  std::vector<glm::vec3> path;
  for (const glm::vec2& p : ellipseArc(centre, glm::vec2(arcRadius), fromDegrees, toDegrees, 48))
    path.emplace_back(p, 0.0f);
  const std::vector<float> radii(path.size(), tubeRadius);
  return tube(std::move(name), path, radii, 24);
}

}  // namespace specula::scene::builtin
