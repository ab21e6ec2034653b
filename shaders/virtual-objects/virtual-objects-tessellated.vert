#version 430 core
// Virtual objects from adaptive tessellation: vertex i of the draw is record i of the finished
// triangles (three records per triangle), already in world space.

#include "common/reflected-vertex.glsl"
#include "common/tessellated-vertex.glsl"
#include "common/virtual-vertex-output.glsl"

layout(std430, binding = 3) readonly buffer TessellatedTriangles {
  TessellatedVertex records[];
};

void main() {
  TessellatedVertex v = records[gl_VertexID];
  emitVirtualVertex(v.positionU.xyz, v.normalV.xyz, vec2(v.positionU.w, v.normalV.w), v.virtualFlags.xyz, v.normalTexelY.xyz,
                    int(v.virtualFlags.w));
}
