#version 430 core
#include "common/shading.glsl"
#include "common/gbuffer-texel.glsl"

in FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;
} inFragment;

uniform float reflectivity;  // the mirror's; its surface colour was already weighted by 1 − reflectivity
uniform int depthOnly;       // 1 in the depth pre-pass: only the nearest virtual surface is shaded
uniform sampler2DArray gbufferPosition;  // w > 0 on this part's texels
uniform sampler2DArray gbufferNormal;
uniform int layer;           // the part's G-buffer layer
uniform int partMask;        // 1: the mirror has several parts, and this one shows only on its own texels
uniform int rayCheck;        // 1 on concave and saddle parts: fragments must lie on this pixel's reflected ray
uniform vec3 eyePosition;

// A fragment whose object point lies further than this (sine of the angle) off the pixel's
// reflected ray belongs to a triangle stretched across two images of a concave part.
const float kOffRaySine = 0.2;

layout(location = 0) out vec4 outColor;

void main() {
  if (partMask != 0 || rayCheck != 0) {
    ivec3 texel = ivec3(gbufferTexelAt(gl_FragCoord.xy), layer);
    vec4 surface = texelFetch(gbufferPosition, texel, 0);
    // Each part of a mirror shows its own reflection: its virtual triangles end at its outline.
    if (surface.w <= 0.0) discard;
    if (rayCheck != 0) {
      vec3 reflected = reflect(normalize(surface.xyz - eyePosition), normalize(texelFetch(gbufferNormal, texel, 0).xyz));
      vec3 toObject = inFragment.worldPosition - surface.xyz;
      if (length(cross(reflected, toObject)) > kOffRaySine * length(toObject) || dot(reflected, toObject) <= 0.0) discard;
    }
  }
  if (depthOnly != 0) {
    outColor = vec4(0.0);
    return;
  }
  vec3 color = shadeSurface(inFragment.worldPosition, inFragment.worldNormal, inFragment.surfaceUv,
                            inFragment.reflectionPoint);
  outColor = vec4(reflectivity * color, 1.0);
}
