#version 430 core
// Mirror surface samples for the search from an analytic mirror (sphere, ellipsoid): ray-cast
// exactly per fragment inside its proxy box, so facets and interpolated normals add no error to the
// reflection points. Mesh mirrors use mirror-gbuffer-mesh.frag.
#include "common/quadric.glsl"

in vec3 worldPosition;

uniform vec3 eyePosition;
uniform mat4 worldToClip;

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  vec3 world, normal;
  if (!eyeRayHitsQuadric(eyePosition, worldPosition - eyePosition, world, normal)) discard;
  outPosition = vec4(world, 1.0);
  outNormal = vec4(normal, 0.0);
  gl_FragDepth = clipDepth(worldToClip, world);
}
