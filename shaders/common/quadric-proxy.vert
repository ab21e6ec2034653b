#version 430 core
// The box around an analytic mirror's quadric, made from gl_VertexID alone (36 vertices, no
// buffers). Drawn instead of the mirror's mesh, whose facets lie inside the quadric and would miss
// its silhouette; the fragment shader ray-casts the exact surface and discards the rest of the box.
#include "common/quadric.glsl"

uniform mat4 worldToClip;

out vec3 worldPosition;  // on the box: the eye ray through it is cast against the quadric
out vec3 worldNormal;    // unused: the quadric gives the normal
out vec2 surfaceUv;      // unused: the quadric gives the uv

// Two triangles per face; corner bits are x, y, z.
const int kCorners[36] = int[36](0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6,  0, 1, 5, 0, 5, 4,
                                 2, 6, 7, 2, 7, 3,  0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5);

void main() {
  int corner = kCorners[gl_VertexID];
  // Slightly larger than the unit cube, so no silhouette texel is lost to rasterization rules.
  vec3 unit = 1.01 * vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, (corner & 4) != 0 ? 1.0 : -1.0);
  vec3 world = (quadricObjectToWorld * vec4(quadricCenter + unit * quadricRadii, 1.0)).xyz;
  worldPosition = world;
  worldNormal = vec3(0.0);
  surfaceUv = vec2(0.0);
  gl_Position = worldToClip * vec4(world, 1.0);
}
