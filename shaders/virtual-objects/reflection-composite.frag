#version 430 core
// Adds one mirror's reflection over its surface, whose own colour was already weighted by
// 1 − reflectivity: what the virtual objects drew into the reflection buffer (reflectivity applied),
// else, where none landed, the background it reflects.
uniform sampler2D reflection;      // linear RGB; alpha 1 where a virtual object or the mirror itself landed
uniform vec3 reflectedBackground;  // background × reflectivity, linear RGB

layout(location = 0) out vec4 outColor;

void main() {
  vec4 reflected = texelFetch(reflection, ivec2(gl_FragCoord.xy), 0);
  outColor = vec4(reflected.a > 0.0 ? reflected.rgb : reflectedBackground, 1.0);
}
