#version 430 core
// Refitting a mesh's hierarchy, step 2, one tree level a dispatch from the deepest up: a leaf's box
// holds its triangles, an inner node's its two children's (refitted by the dispatch before).
layout(local_size_x = 64) in;

#include "common/triangle-bvh-records.glsl"

layout(std430, binding = 0) buffer BvhNodes {
  BvhNode bvhNodes[];
};
layout(std430, binding = 1) readonly buffer BvhTriangles {
  BvhTriangle bvhTriangles[];
};
layout(std430, binding = 2) readonly buffer LevelOrder {
  uint levelOrder[];  // node indices, deepest level first
};

uniform uint firstInLevel;
uniform uint levelSize;

void main() {
  if (gl_GlobalInvocationID.x >= levelSize) return;
  uint n = levelOrder[firstInLevel + gl_GlobalInvocationID.x];
  BvhNode node = bvhNodes[n];
  vec3 low = vec3(3.4e38), high = vec3(-3.4e38);
  if (node.count > 0u) {
    for (uint t = node.first; t < node.first + node.count; ++t) {
      BvhTriangle triangle = bvhTriangles[t];
      low = min(low, min(triangle.a, min(triangle.b, triangle.c)));
      high = max(high, max(triangle.a, max(triangle.b, triangle.c)));
    }
  } else {
    low = min(bvhNodes[node.first].low, bvhNodes[node.first + 1u].low);
    high = max(bvhNodes[node.first].high, bvhNodes[node.first + 1u].high);
  }
  bvhNodes[n].low = low;
  bvhNodes[n].high = high;
}
