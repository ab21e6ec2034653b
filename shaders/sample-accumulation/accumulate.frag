#version 430 core
// Adds one jittered frame's colour, weighted, to the running sum (additive blending into RGBA32F).
uniform sampler2D frame;  // the sRGB frame: fetching decodes it to linear
uniform float weight;     // 1 / samples

layout(location = 0) out vec4 outColor;

void main() {
  outColor = weight * texelFetch(frame, ivec2(gl_FragCoord.xy), 0);
}
