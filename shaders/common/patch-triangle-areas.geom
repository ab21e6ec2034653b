#version 430 core
// Measures what the patch tessellation made (passes::PatchTessellationProbe): counts every triangle
// and records its area on screen in pixels; -1 for one reaching behind the eye, -2 for one wholly off
// screen. Emits nothing: the probe draws with rasterization discarded.

layout(triangles) in;
layout(points, max_vertices = 1) out;

uniform vec2 viewportPixels;
uniform uint capacity;  // areas the buffer holds; the count goes on past it

layout(std430, binding = 2) buffer TriangleAreas {
  uint triangleCount;
  float areas[];
};

void main() {
  uint index = atomicAdd(triangleCount, 1u);
  if (index >= capacity) return;
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position, c = gl_in[2].gl_Position;
  if (min(a.w, min(b.w, c.w)) <= 0.0) {
    areas[index] = -1.0;
    return;
  }
  vec2 halfViewport = 0.5 * viewportPixels;
  vec2 sa = a.xy / a.w * halfViewport, sb = b.xy / b.w * halfViewport, sc = c.xy / c.w * halfViewport;
  vec2 low = min(sa, min(sb, sc)), high = max(sa, max(sb, sc));
  bool offScreen = any(greaterThan(low, halfViewport)) || any(lessThan(high, -halfViewport));
  vec2 ab = sb - sa, ac = sc - sa;
  areas[index] = offScreen ? -2.0 : 0.5 * abs(ab.x * ac.y - ab.y * ac.x);
}
