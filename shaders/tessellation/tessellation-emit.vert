#version 440 core
// Feeds the emit geometry shader: working triangle t's corner i (vertex 3t + i of a draw with no
// vertex arrays), the new vertex on its edge i and the triangle's split mask.
#include "common/reflected-vertex.glsl"
#include "common/edge-split.glsl"

layout(std430, binding = 3) readonly buffer WorkingTriangles {
  TessellatedVertex records[];
};
layout(std430, binding = 4) readonly buffer EdgeSplits {
  EdgeSplit splits[];
};

uniform int finishAll;  // 1 in the last round: nothing splits

out CornerData {
  TessellatedVertex corner;
  TessellatedVertex midpoint;  // on the edge to the next corner
  flat int mask;
} outCorner;

void main() {
  int triangle = gl_VertexID / 3, corner = gl_VertexID % 3;
  outCorner.corner = records[gl_VertexID];
  if (finishAll != 0) {
    outCorner.midpoint = outCorner.corner;
    outCorner.mask = 0;
    return;
  }
  outCorner.midpoint = splits[triangle].midpoint[corner];
  outCorner.mask = splits[triangle].mask.x;
}
