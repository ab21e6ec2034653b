#version 430 core
// The environment-map lookup for one mirror pixel: the eye ray reflected about the G-buffer's
// normal there, looked up in the cube map captured from the mirror's centre; where the planner
// chose it for a mirror among searched ones, only the pixels it serves within the error budget.
#include "common/environment.glsl"
#include "common/environment-bound.glsl"
#include "common/gbuffer-texel.glsl"

uniform sampler2DArray gbufferPosition;  // w > 0 on mirror texels
uniform sampler2DArray gbufferNormal;
uniform samplerCube environment;         // linear RGB, alpha the share of the texel the captured objects cover
uniform int layer;
uniform vec3 eyePosition;
uniform float reflectivity;     // the mirror's; its surface colour was already weighted by 1 − reflectivity

layout(location = 0) out vec4 outColor;

void main() {
  vec3 position, normal;
  // Another part of the mirror, or outside its (closed twin's) surface.
  if (!gbufferAtPixel(gbufferPosition, gbufferNormal, layer, gl_FragCoord.xy, position, normal)) discard;
  if (!environmentLookupHolds(position, normal, eyePosition)) discard;  // ray-cast by the virtual-objects pass
  vec3 reflected = reflect(normalize(position - eyePosition), normal);
  vec4 captured = texture(environment, reflected);  // cleared to 0: premultiplied, so filtering blends right
  outColor = vec4(reflectivity * (captured.rgb + (1.0 - captured.a) * environmentRadiance(reflected)), 1.0);
}
