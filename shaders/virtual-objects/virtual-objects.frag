#version 430 core
#include "common/shading.glsl"

in FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;
} inFragment;

uniform float reflectivity;  // the mirror's; its surface colour was already weighted by 1 − reflectivity
uniform int depthOnly;       // 1 in the depth pre-pass: only the nearest virtual surface is shaded

layout(location = 0) out vec4 outColor;

void main() {
  if (depthOnly != 0) {
    outColor = vec4(0.0);
    return;
  }
  vec3 color = shadeSurface(inFragment.worldPosition, inFragment.worldNormal, inFragment.surfaceUv,
                            inFragment.reflectionPoint);
  outColor = vec4(reflectivity * color, 1.0);
}
