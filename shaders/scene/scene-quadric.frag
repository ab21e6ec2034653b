#version 430 core
// An analytic mirror seen directly: its exact quadric ray-cast inside the proxy box, so its
// silhouette, depth and stencil are the quadric's and not its mesh's (which the ray tracer ignores).
#include "common/quadric.glsl"
#include "common/shading.glsl"

in vec3 worldPosition;

uniform vec3 eyePosition;
uniform mat4 worldToClip;
uniform float surfaceWeight;  // 1 − reflectivity when the mirror's reflection is drawn, else 1

layout(location = 0) out vec4 outColor;

void main() {
  // The finest level, as the reference samples analytic surfaces: uv derivatives past a discard are undefined.
  vec3 position, normal;
  if (!eyeRayHitsQuadric(eyePosition, worldPosition - eyePosition, position, normal)) discard;
  outColor = vec4(surfaceWeight * shadeSurfaceOver(position, normal, quadricUv(position), 0.0, eyePosition), 1.0);
  gl_FragDepth = clipDepth(worldToClip, position);
}
