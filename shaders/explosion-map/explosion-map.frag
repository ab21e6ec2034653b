#version 430 core
// A map texel: the mirror position and (fixed) normal interpolated over the triangle at the texel's
// direction — the paper's barycentric weights, computed by the rasterizer — and what covers it.
in vec3 worldPosition;
in vec3 worldNormal;
flat in float kind;

layout(location = 0) out vec4 outPosition;  // w: 1 mirror triangle, 2 extension polygon, 0 empty
layout(location = 1) out vec4 outNormal;

void main() {
  outPosition = vec4(worldPosition, kind);
  outNormal = vec4(normalize(worldNormal), 0.0);
}
