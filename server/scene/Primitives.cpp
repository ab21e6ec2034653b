#include "scene/Primitives.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <utility>
#include <vector>

namespace specula::scene::primitives {

namespace {

// One circle of a surface of revolution: a point of the (radius, y) profile with its unit normal
// in the same (radial, y) plane and its v texture coordinate.
struct Ring {
  float radius = 0.0f;
  float y = 0.0f;
  glm::vec2 normal{1.0f, 0.0f};
  float v = 0.0f;
};

// Direction of slice angle phi about +y; (cos, 0, -sin) is the right-handed rotation of +x, which
// makes (slice, profile-upwards) quads counter-clockwise seen from outside.
glm::vec3 sliceDirection(int slice, int slices) {
  const float phi = glm::two_pi<float>() * static_cast<float>(slice % slices) / static_cast<float>(slices);
  return {std::cos(phi), 0.0f, -std::sin(phi)};
}

// Sweeps rings about +y. Consecutive rings are joined by a band unless they coincide (a crease, where
// the ring is repeated with a second normal); triangles collapsing on the axis are left out.
Mesh sweep(std::string name, const std::vector<Ring>& rings, int slices) {
  assert(slices >= 3 && rings.size() >= 2);
  Mesh mesh{std::move(name), {}, {}};
  const auto columns = static_cast<std::uint32_t>(slices + 1);  // the seam column repeats column 0
  mesh.vertices.reserve(rings.size() * columns);
  for (const Ring& ring : rings)
    for (int i = 0; i <= slices; ++i) {
      const glm::vec3 d = sliceDirection(i, slices);
      mesh.vertices.push_back({{d.x * ring.radius, ring.y, d.z * ring.radius},
                               glm::normalize(glm::vec3(d.x * ring.normal.x, ring.normal.y, d.z * ring.normal.x)),
                               {static_cast<float>(i) / static_cast<float>(slices), ring.v}});
    }
  for (std::size_t j = 0; j + 1 < rings.size(); ++j) {
    const Ring& lower = rings[j];
    const Ring& upper = rings[j + 1];
    if (lower.radius == upper.radius && lower.y == upper.y) continue;
    const auto row = static_cast<std::uint32_t>(j) * columns;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i) {
      const std::uint32_t a = row + i, b = a + 1, c = b + columns, d = a + columns;
      if (lower.radius > 0.0f) mesh.indices.insert(mesh.indices.end(), {a, b, c});
      if (upper.radius > 0.0f) mesh.indices.insert(mesh.indices.end(), {a, c, d});
    }
  }
  return mesh;
}

// Outward normal of a profile segment: its direction turned a quarter clockwise in (radius, y).
glm::vec2 segmentNormal(const glm::vec2& from, const glm::vec2& to) {
  const glm::vec2 t = glm::normalize(to - from);
  return {t.y, -t.x};
}

// Profile corners sharper than this keep one normal per side instead of a blended one.
constexpr float kCreaseCosine = 0.866f;  // cos 30°

}  // namespace

Mesh grid(std::string name, float sizeX, float sizeZ, int cellsX, int cellsZ) {
  assert(cellsX >= 1 && cellsZ >= 1);
  Mesh mesh{std::move(name), {}, {}};
  const auto columns = static_cast<std::uint32_t>(cellsX + 1);
  for (int k = 0; k <= cellsZ; ++k)
    for (int i = 0; i <= cellsX; ++i) {
      const float x = sizeX * (static_cast<float>(i) / static_cast<float>(cellsX) - 0.5f);
      const float z = sizeZ * (static_cast<float>(k) / static_cast<float>(cellsZ) - 0.5f);
      mesh.vertices.push_back({{x, 0.0f, z}, {0.0f, 1.0f, 0.0f}, {x, z}});
    }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(cellsZ); ++k)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cellsX); ++i) {
      const std::uint32_t a = k * columns + i, b = a + 1, c = a + columns, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});  // +z then +x turns counter-clockwise about +y
    }
  return mesh;
}

Mesh uvSphere(std::string name, float radius, int slices, int stacks) {
  assert(stacks >= 2);
  std::vector<Ring> rings;
  for (int j = 0; j <= stacks; ++j) {
    const float theta = glm::pi<float>() * static_cast<float>(j) / static_cast<float>(stacks);  // from the south pole
    // Exactly on the axis at the poles, so the pole triangles collapse cleanly and are left out.
    const glm::vec2 n{j == 0 || j == stacks ? 0.0f : std::sin(theta), -std::cos(theta)};
    rings.push_back({radius * n.x, radius * n.y, n, static_cast<float>(j) / static_cast<float>(stacks)});
  }
  return sweep(std::move(name), rings, slices);
}

Mesh box(std::string name, const glm::vec3& size) {
  Mesh mesh{std::move(name), {}, {}};
  const glm::vec3 h = size * 0.5f;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 n{0.0f};
      n[axis] = sign;
      // (u, v) span the face so that u × v = n: counter-clockwise seen from outside.
      glm::vec3 u{0.0f}, v{0.0f};
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = sign;
      const glm::vec3 centre = n * h;
      const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
      for (const glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
        const glm::vec3 p = centre + (corner.x - 0.5f) * 2.0f * u * h + (corner.y - 0.5f) * 2.0f * v * h;
        mesh.vertices.push_back({p, n, corner});
      }
      mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  return mesh;
}

Mesh cylinder(std::string name, float radius, float height, int slices, bool capped) {
  if (!capped) {
    const std::vector<Ring> rings{{radius, 0.0f, {1.0f, 0.0f}, 0.0f}, {radius, height, {1.0f, 0.0f}, 1.0f}};
    return sweep(std::move(name), rings, slices);
  }
  const glm::vec2 profile[] = {{0.0f, 0.0f}, {radius, 0.0f}, {radius, height}, {0.0f, height}};
  return lathe(std::move(name), profile, slices);
}

Mesh torus(std::string name, float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
  assert(minorSegments >= 3);
  std::vector<Ring> rings;
  for (int k = 0; k <= minorSegments; ++k) {
    // Starts on the inner equator and walks up the outside, so the tube is swept counter-clockwise.
    const float fraction = static_cast<float>(k % minorSegments) / static_cast<float>(minorSegments);
    const float alpha = glm::pi<float>() + glm::two_pi<float>() * fraction;
    const glm::vec2 n{std::cos(alpha), std::sin(alpha)};
    rings.push_back({majorRadius + minorRadius * n.x, minorRadius * n.y, n,
                     static_cast<float>(k) / static_cast<float>(minorSegments)});
  }
  return sweep(std::move(name), rings, majorSegments);
}

Mesh lathe(std::string name, std::span<const glm::vec2> profile, int slices) {
  // Rounding leaves arcs a hair off the axis or off their neighbours: snap radii within a tolerance
  // onto the axis (so poles close without slivers) and drop points repeated within it (no tangent).
  float extent = 0.0f;
  for (const glm::vec2& p : profile) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  const float tolerance = 1e-5f * extent;
  std::vector<glm::vec2> points;
  for (glm::vec2 p : profile) {
    assert(p.x >= -tolerance);
    if (p.x < tolerance) p.x = 0.0f;
    if (points.empty() || glm::distance(p, points.back()) > tolerance) points.push_back(p);
  }
  if (points.size() < 2) return Mesh{std::move(name), {}, {}};  // a profile without length sweeps no surface
  std::vector<float> arc{0.0f};
  for (std::size_t k = 1; k < points.size(); ++k) arc.push_back(arc.back() + glm::distance(points[k - 1], points[k]));

  std::vector<Ring> rings;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const float v = arc[k] / arc.back();
    const auto ring = [&](const glm::vec2& n) { rings.push_back({points[k].x, points[k].y, n, v}); };
    if (k == 0) {
      ring(segmentNormal(points[0], points[1]));
    } else if (k + 1 == points.size()) {
      ring(segmentNormal(points[k - 1], points[k]));
    } else {
      const glm::vec2 before = segmentNormal(points[k - 1], points[k]);
      const glm::vec2 after = segmentNormal(points[k], points[k + 1]);
      if (glm::dot(before, after) >= kCreaseCosine) {
        ring(glm::normalize(before + after));
      } else {
        ring(before);
        ring(after);
      }
    }
  }
  return sweep(std::move(name), rings, slices);
}

void append(Mesh& into, const Mesh& part, const glm::mat4& transform) {
  const glm::mat3 normalTransform = glm::transpose(glm::inverse(glm::mat3(transform)));
  const auto base = static_cast<std::uint32_t>(into.vertices.size());
  into.vertices.reserve(into.vertices.size() + part.vertices.size());
  for (const Vertex& v : part.vertices)
    into.vertices.push_back(
        {glm::vec3(transform * glm::vec4(v.position, 1.0f)), glm::normalize(normalTransform * v.normal), v.uv});
  // A mirroring transform turns every triangle over; swapping two corners keeps the front faces outside.
  const bool flips = glm::determinant(glm::mat3(transform)) < 0.0f;
  into.indices.reserve(into.indices.size() + part.indices.size());
  for (std::size_t t = 0; t < part.indices.size(); t += 3) {
    const std::uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
    into.indices.insert(into.indices.end(), {base + a, base + (flips ? c : b), base + (flips ? b : c)});
  }
}

}  // namespace specula::scene::primitives
