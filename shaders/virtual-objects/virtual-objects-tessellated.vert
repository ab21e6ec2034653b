#version 430 core
// Virtual objects from adaptive tessellation: vertex i of the draw is record i of the finished
// triangles (three records per triangle), already in world space; each reads its whole triangle.
#include "common/tessellation-records.glsl"
#include "virtual-objects/virtual-triangle.glsl"

layout(std430, binding = VIRTUAL_OBJECTS_TRIANGLES_BINDING) readonly buffer TessellatedTriangles {
  TessellatedVertex records[];
};

void main() {
  int first = gl_VertexID - gl_VertexID % 3;
  TessellatedVertex c[3] = TessellatedVertex[3](records[first], records[first + 1], records[first + 2]);
  vec4 position[3];
  // A dropped triangle collapses to a point beyond the far plane.
  gl_Position = placeVirtualTriangle(c, position) ? position[gl_VertexID % 3] : vec4(0.0, 0.0, 2.0, 1.0);
  writeVirtualCorner(c, gl_VertexID % 3);
}
