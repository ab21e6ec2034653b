#version 430 core
// Places one virtual triangle of a mesh-drawn object (virtual-triangle.glsl), or drops it.
#include "virtual-objects/virtual-triangle.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in CornerData {
  TessellatedVertex corner;
} inCorner[];

void main() {
  TessellatedVertex c[3] = TessellatedVertex[3](inCorner[0].corner, inCorner[1].corner, inCorner[2].corner);
  vec4 position[3];
  if (!placeVirtualTriangle(c, position)) return;
  for (int k = 0; k < 3; ++k) {
    writeVirtualCorner(c, k);
    gl_Position = position[k];
    EmitVertex();
  }
  EndPrimitive();
}
