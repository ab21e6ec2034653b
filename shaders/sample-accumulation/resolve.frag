#version 430 core
// Writes the averaged linear colour into the frame (sRGB-encoded on write).
uniform sampler2D sum;

layout(location = 0) out vec4 outColor;

void main() {
  outColor = texelFetch(sum, ivec2(gl_FragCoord.xy), 0);
}
