#version 430 core
// One point at the centre of each listed uncovered pixel (uncovered-pixels.comp): the ray-cast
// fragment shader then runs at those pixels only.
#include "virtual-objects/uncovered-pixels.glsl"

uniform vec2 frameSize;  // pixels

void main() {
  uint xy = uncoveredPixel[gl_VertexID];
  vec2 centre = vec2(xy & 0xFFFFu, xy >> 16) + 0.5;
  gl_Position = vec4(centre / frameSize * 2.0 - 1.0, 1.0, 1.0);
}
