#version 430 core
// The environment behind everything: drawn on the far plane after the scene, where nothing was drawn.
#include "common/environment.glsl"

uniform mat4 clipToWorld;
uniform vec2 frameSize;

layout(location = 0) out vec4 outColor;

void main() {
  vec2 ndc = gl_FragCoord.xy / frameSize * 2.0 - 1.0;
  vec4 near = clipToWorld * vec4(ndc, -1.0, 1.0);
  vec4 far = clipToWorld * vec4(ndc, 1.0, 1.0);
  outColor = vec4(environmentRadiance(far.xyz / far.w - near.xyz / near.w), 1.0);
}
