#version 430 core
// Level 0 of the ray hierarchy (common/ray-hierarchy.glsl) from the mirror G-buffer: each mirror
// texel's position and reflected eye ray. Szabo's leaves have radius and angle zero, so a vertex whose
// ray passes between samples lies in no leaf (his "holes"); ours bound the texel's whole cell, half
// way to the farthest neighbour (a corner is half a diagonal away), so the continuous mirror is covered.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/ray-hierarchy.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray spheres;
layout(rgba32f, binding = 1) uniform writeonly image2DArray cones;
uniform sampler2DArray gbufferPosition;  // w > 0 on mirror texels
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform ivec2 origin;  // first texel to rebuild
uniform ivec2 extent;  // texels to rebuild from there
uniform vec3 eyePosition;

bool reflectedRayAt(ivec2 texel, out vec3 position, out vec3 direction) {
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, textureSize(gbufferPosition, 0).xy))) return false;
  vec4 p = texelFetch(gbufferPosition, ivec3(texel, layer), 0);
  if (p.w <= 0.0) return false;
  position = p.xyz;
  direction = reflect(normalize(p.xyz - eyePosition), normalize(texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz));
  return true;
}

void main() {
  if (any(greaterThanEqual(ivec2(gl_GlobalInvocationID.xy), extent))) return;
  ivec2 texel = origin + ivec2(gl_GlobalInvocationID.xy);
  vec3 position, direction;
  if (!reflectedRayAt(texel, position, direction)) {
    imageStore(spheres, ivec3(texel, layer), vec4(0.0, 0.0, 0.0, -1.0));
    imageStore(cones, ivec3(texel, layer), vec4(0.0, 0.0, 0.0, -1.0));
    return;
  }
  float radius = 0.0, angle = 0.0;
  bool rim = false;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      vec3 neighbourPosition, neighbourDirection;
      if (!reflectedRayAt(texel + ivec2(dx, dy), neighbourPosition, neighbourDirection)) {
        rim = true;
        continue;
      }
      radius = max(radius, distance(position, neighbourPosition));
      angle = max(angle, angleBetween(direction, neighbourDirection));
    }
  }
  radius *= 0.5;
  angle *= 0.5;
  if (rim) {
    // Between a rim texel's centre and the mirror's edge lies half a cell more, and at a silhouette
    // the reflected rays turn all the way to the eye ray itself (N perpendicular to the view): the
    // region behind the mirror is reflected in that sliver, so the leaf must hold both.
    radius *= 2.0;
    angle = max(angle, angleBetween(direction, normalize(position - eyePosition)));
  }
  imageStore(spheres, ivec3(texel, layer), vec4(position, radius));
  imageStore(cones, ivec3(texel, layer), vec4(direction, angle));
}
