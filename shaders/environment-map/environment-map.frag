#version 430 core
// The environment-map lookup for one mirror pixel: the eye ray reflected about the G-buffer's
// normal there, looked up in the cube map captured from the mirror's centre.
#include "common/gbuffer-texel.glsl"

uniform sampler2DArray gbufferPosition;  // w > 0 on mirror texels
uniform sampler2DArray gbufferNormal;
uniform samplerCube environment;         // linear RGB
uniform int layer;
uniform vec3 eyePosition;
uniform float reflectivity;     // the mirror's; its surface colour was already weighted by 1 − reflectivity

layout(location = 0) out vec4 outColor;

void main() {
  ivec2 texel = gbufferTexelAt(gl_FragCoord.xy);
  vec4 position = texelFetch(gbufferPosition, ivec3(texel, layer), 0);
  if (position.w <= 0.0) discard;  // another part of the mirror, or outside its (closed twin's) surface
  vec3 normal = texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz;
  vec3 reflected = reflect(normalize(position.xyz - eyePosition), normal);
  outColor = vec4(reflectivity * texture(environment, reflected).rgb, 1.0);
}
