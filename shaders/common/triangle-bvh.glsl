// The nearest hit of a ray with a mirror's own mesh through its bounding-volume hierarchy: the
// GLSL twin of math::TriangleBvh::intersect (same layout, same Möller–Trumbore test, same nearest
// hit; this one opens the nearer child first, which only changes how soon it is found).

#include "common/triangle-bvh-records.glsl"

layout(std430, binding = 4) readonly buffer BvhNodes {
  BvhNode bvhNodes[];
};
layout(std430, binding = 5) readonly buffer BvhTriangles {
  BvhTriangle bvhTriangles[];
};

const int kBvhStackSize = 32;  // math::TriangleBvh::kMaxDepth

// Where the ray enters the node's box within (tMin, tMax), or a negative value when it misses it.
float bvhBoxEntry(BvhNode node, vec3 origin, vec3 inverseDirection, float tMin, float tMax) {
  vec3 t0 = (node.low - origin) * inverseDirection, t1 = (node.high - origin) * inverseDirection;
  vec3 near = min(t0, t1), far = max(t0, t1);
  float entry = max(max(near.x, near.y), max(near.z, tMin));
  return entry <= min(min(far.x, far.y), min(far.z, tMax)) ? entry : -1.0;
}

// Distance (in units of `direction`) in (tMin, tMax), the mesh's triangle and the barycentric
// weights of its second and third corners; false when nothing is hit. Front to back: of an inner
// node's children the nearer is visited first, and a node entered beyond the nearest hit so far is
// skipped, so a hit prunes the rest of the tree instead of every box being opened.
bool intersectBvh(vec3 origin, vec3 direction, float tMin, float tMax, out float distance, out uint triangle,
                  out vec2 barycentric) {
  vec3 inverseDirection = 1.0 / direction;
  uint stack[kBvhStackSize];
  float stackEntry[kBvhStackSize];
  int depth = 0;
  float rootEntry = bvhBoxEntry(bvhNodes[0], origin, inverseDirection, tMin, tMax);
  if (rootEntry >= 0.0) {
    stack[depth] = 0u;
    stackEntry[depth++] = rootEntry;
  }
  bool hit = false;
  while (depth > 0) {
    --depth;
    if (stackEntry[depth] > tMax) continue;  // entered beyond the nearest hit found since it was pushed
    BvhNode node = bvhNodes[stack[depth]];
    if (node.count == 0u) {
      float first = bvhBoxEntry(bvhNodes[node.first], origin, inverseDirection, tMin, tMax);
      float second = bvhBoxEntry(bvhNodes[node.first + 1u], origin, inverseDirection, tMin, tMax);
      if (depth + 2 > kBvhStackSize) continue;  // cannot happen for a tree built within kMaxDepth
      bool secondNearer = second >= 0.0 && (first < 0.0 || second < first);
      // Pushed far, then near: the near child is popped first.
      if (secondNearer) {
        if (first >= 0.0) {
          stack[depth] = node.first;
          stackEntry[depth++] = first;
        }
        stack[depth] = node.first + 1u;
        stackEntry[depth++] = second;
      } else {
        if (second >= 0.0) {
          stack[depth] = node.first + 1u;
          stackEntry[depth++] = second;
        }
        if (first >= 0.0) {
          stack[depth] = node.first;
          stackEntry[depth++] = first;
        }
      }
      continue;
    }
    for (uint i = node.first; i < node.first + node.count; ++i) {
      BvhTriangle candidate = bvhTriangles[i];
      vec3 e1 = candidate.b - candidate.a, e2 = candidate.c - candidate.a;
      vec3 p = cross(direction, e2);
      float determinant = dot(e1, p);
      if (determinant == 0.0) continue;
      float inverseDeterminant = 1.0 / determinant;
      vec3 s = origin - candidate.a;
      float u = dot(s, p) * inverseDeterminant;
      if (u < 0.0 || u > 1.0) continue;
      vec3 q = cross(s, e1);
      float v = dot(direction, q) * inverseDeterminant;
      if (v < 0.0 || u + v > 1.0) continue;
      float t = dot(e2, q) * inverseDeterminant;
      if (t <= tMin || t >= tMax) continue;
      tMax = t;
      distance = t;
      triangle = candidate.index;
      barycentric = vec2(u, v);
      hit = true;
    }
  }
  return hit;
}
