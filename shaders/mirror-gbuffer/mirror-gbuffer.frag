#version 430 core
// Mirror surface samples for the search. A mirror with an analytic shape (sphere, ellipsoid) is
// ray-cast exactly per fragment: its mesh only bounds it, so facets and interpolated normals add
// no error to the reflection points.
#include "common/quadric.glsl"

in vec3 worldPosition;
in vec3 worldNormal;

uniform vec3 eyePosition;
uniform mat4 worldToClip;

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  if (analytic == 0) {
    outPosition = vec4(worldPosition, 1.0);
    outNormal = vec4(normalize(worldNormal), 0.0);
    return;
  }
  vec3 world, normal;
  if (!eyeRayHitsQuadric(eyePosition, worldPosition - eyePosition, world, normal)) discard;
  outPosition = vec4(world, 1.0);
  outNormal = vec4(normal, 0.0);
  vec4 clip = worldToClip * vec4(world, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}
