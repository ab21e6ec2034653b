#version 430 core
// Adds one mirror's reflection over its surface, whose own colour was already weighted by
// 1 − reflectivity: what the virtual objects drew into the reflection buffer (reflectivity applied),
// over the environment each part wrote there first. On a mirror the environment map serves, only
// the pixels it cannot serve (the environment-map pass adds the others).
#include "common/environment-bound.glsl"
#include "common/gbuffer-texel.glsl"

uniform sampler2D reflection;      // linear RGB; alpha 1 where a virtual object or the mirror itself landed
uniform int environmentLayer;      // the G-buffer layer of a mirror the environment map serves; -1: none
uniform sampler2DArray gbufferPosition;
uniform sampler2DArray gbufferNormal;
uniform vec3 eyePosition;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 surface, normal;
  if (environmentLayer >= 0 && gbufferAtPixel(gbufferPosition, gbufferNormal, environmentLayer, gl_FragCoord.xy, surface, normal) &&
      environmentLookupHolds(surface, normal, eyePosition))
    discard;
  outColor = vec4(texelFetch(reflection, ivec2(gl_FragCoord.xy), 0).rgb, 1.0);
}
