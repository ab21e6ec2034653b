#version 430 core
#include "common/shading.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec2 surfaceUv;

uniform vec3 eyePosition;
uniform float surfaceWeight;  // 1 − reflectivity for mirrors whose reflection is drawn, else 1

layout(location = 0) out vec4 outColor;

void main() {
  outColor = vec4(surfaceWeight * shadeSurface(worldPosition, worldNormal, surfaceUv, dFdx(surfaceUv), dFdy(surfaceUv), eyePosition), 1.0);
}
