#version 440 core
// Feeds the emit geometry shader: working triangle t's corner i (vertex 3t + i of a draw with no
// vertex arrays, whose first vertex is the object's first), the new vertex on its edge i and the
// triangle's split mask.
#include "common/reflected-vertex.glsl"
#include "common/edge-split.glsl"

layout(std430, binding = 3) readonly buffer WorkingTriangles {
  TessellatedVertex records[];
};
layout(std430, binding = 4) readonly buffer EdgeSplits {
  EdgeSplit splits[];
};

uniform int finishAll;     // 1 in the last round: nothing splits
uniform int emitChildren;  // as in tessellation-emit.geom

out CornerData {
  TessellatedVertex corner;
  TessellatedVertex midpoint;  // on the edge to the next corner
  flat int mask;
} outCorner;

void main() {
  int triangle = gl_VertexID / 3, corner = gl_VertexID % 3;
  outCorner.corner = records[gl_VertexID];
  outCorner.mask = finishAll != 0 ? 0 : splits[triangle].mask.x;
  // Only a split edge has a midpoint, and only children need it.
  bool needed = emitChildren != 0 && (outCorner.mask & (1 << corner)) != 0;
  outCorner.midpoint = needed ? splits[triangle].midpoint[corner] : outCorner.corner;
}
