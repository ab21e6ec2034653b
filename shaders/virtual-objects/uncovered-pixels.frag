#version 430 core
// Drawn over one mirror part's stencil: lists the pixels of the part where the reflection buffer
// is still empty (no virtual object's triangle was proposed there) but whose reflected ray meets
// the bounding box of an object reflected in the part. Where a reflected image is squeezed against
// a silhouette, rim or horizon, its triangles' flat approximation and widening can fall short of
// it; those pixels are then ray-cast (ray-cast.frag) instead of showing the background. Rays that
// meet no box (most of the sky in a mirror) would find nothing: they are not listed.
#include "common/environment-bound.glsl"
#include "common/gbuffer-texel.glsl"
#include "virtual-objects/uncovered-pixels.glsl"

layout(early_fragment_tests) in;  // only the part's stencil runs it (it writes no colour or depth)

uniform sampler2D reflection;  // alpha > 0 where something landed
uniform sampler2DArray gbufferPosition;  // w > 0 on this part's texels
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform vec3 eyePosition;
uniform int boxCount;
// 1 on a part the environment map serves: list instead the pixels its lookup cannot serve.
uniform int environmentPart;

layout(std430, binding = 9) readonly buffer ReflectedBoxes {
  vec4 reflectedBox[];  // world bounds of each reflected object: low, high
};

void main() {
  if (environmentPart == 0 && texelFetch(reflection, ivec2(gl_FragCoord.xy), 0).a > 0.0) return;
  vec3 surface, normal;
  if (!gbufferAtPixel(gbufferPosition, gbufferNormal, layer, gl_FragCoord.xy, surface, normal)) return;
  if (environmentPart != 0 && environmentLookupHolds(surface, normal, eyePosition)) return;
  vec3 inverseDirection = 1.0 / reflect(normalize(surface - eyePosition), normal);
  bool meetsSome = false;
  for (int i = 0; i < boxCount && !meetsSome; ++i) {
    vec3 t0 = (reflectedBox[2 * i].xyz - surface) * inverseDirection, t1 = (reflectedBox[2 * i + 1].xyz - surface) * inverseDirection;
    vec3 near = min(t0, t1), far = max(t0, t1);
    meetsSome = max(max(near.x, near.y), max(near.z, 0.0)) <= min(min(far.x, far.y), far.z);
  }
  if (meetsSome) uncoveredPixel[atomicAdd(drawCount, 1u)] = uint(gl_FragCoord.x) | (uint(gl_FragCoord.y) << 16);
}
