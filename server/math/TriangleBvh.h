#pragma once
// A bounding-volume hierarchy over a triangle mesh, laid out for a GPU storage buffer
// (shaders/common/triangle-bvh.glsl traverses it): a mirror's own mesh, against which its reflected
// rays are cast to find where the mirror sees itself. Built once per mesh, in the mesh's own space.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace specula::math {

class TriangleBvh {
 public:
  // std430 twin of BvhNode in triangle-bvh-records.glsl. An inner node's children are at `first` and
  // first + 1; a leaf (count > 0) holds triangles first .. first + count − 1 of triangles().
  struct Node {
    glm::vec3 low;
    std::uint32_t first;
    glm::vec3 high;
    std::uint32_t count;
  };
  static_assert(sizeof(Node) == 32, "must match BvhNode in triangle-bvh-records.glsl");

  // std430 twin of BvhTriangle: corners in the mesh's space and the mesh's index of the triangle.
  struct Triangle {
    glm::vec3 a;
    std::uint32_t index;
    glm::vec3 b;
    float unused0;
    glm::vec3 c;
    float unused1;
  };
  static_assert(sizeof(Triangle) == 48, "must match BvhTriangle in triangle-bvh-records.glsl");

  struct Hit {
    float distance;          // along the (not necessarily unit) direction, in its units
    std::uint32_t triangle;  // index into the mesh's triangles
    glm::vec2 barycentric;   // weights of the triangle's second and third corners
  };

  static constexpr int kMaxDepth = 32;  // the GLSL traversal's stack holds this many nodes

  // positions: the mesh's vertices; indices: three per triangle. Degenerate triangles are kept (no
  // ray hits them). An empty mesh gives no nodes at all.
  static TriangleBvh build(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }

  // The nearest hit with distance in (minDistance, maxDistance); the same test the GLSL runs.
  std::optional<Hit> intersect(const glm::vec3& origin, const glm::vec3& direction, float minDistance,
                               float maxDistance) const;

 private:
  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;
};

}  // namespace specula::math
