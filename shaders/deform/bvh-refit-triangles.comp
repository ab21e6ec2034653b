#version 430 core
// Refitting a mesh's hierarchy after it changed shape, step 1: every triangle record takes its corners
// from the mesh's vertices as they are now (its topology, so the tree's order, stays).
layout(local_size_x = 64) in;

#include "common/triangle-bvh-records.glsl"

layout(std430, binding = 0) readonly buffer MeshVertices {
  float meshVertex[];  // scene::Vertex: 8 floats
};
layout(std430, binding = 1) readonly buffer MeshIndices {
  uint meshIndex[];
};
layout(std430, binding = 2) buffer BvhTriangles {
  BvhTriangle bvhTriangles[];
};

uniform uint triangleCount;

vec3 corner(uint triangle, uint k) {
  uint v = meshIndex[3u * triangle + k];
  return vec3(meshVertex[8u * v], meshVertex[8u * v + 1u], meshVertex[8u * v + 2u]);
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= triangleCount) return;
  uint triangle = bvhTriangles[t].index;
  bvhTriangles[t].a = corner(triangle, 0u);
  bvhTriangles[t].b = corner(triangle, 1u);
  bvhTriangles[t].c = corner(triangle, 2u);
}
