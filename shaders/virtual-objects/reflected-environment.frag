#version 430 core
// What one mirror part reflects where its reflected ray meets nothing: the environment in the reflected
// direction, written into the reflection buffer before the part's virtual objects (which cover it where they
// land). Alpha stays 0: nothing has landed here yet, so the uncovered-pixel search still finds the pixel.
#include "common/environment.glsl"
#include "common/gbuffer-texel.glsl"

uniform sampler2DArray gbufferPosition;
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform vec3 eyePosition;
uniform float reflectivity;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 position, normal;
  if (!gbufferAtPixel(gbufferPosition, gbufferNormal, layer, gl_FragCoord.xy, position, normal)) discard;
  outColor = vec4(reflectivity * environmentRadiance(reflect(normalize(position - eyePosition), normal)), 0.0);
}
