#version 440 core
// Writes one round's output by transform feedback: the unsplit triangles to the finished list, or
// the split ones' children to the next working list. Crack-free patterns by number of split edges:
// one → 2 triangles, two → 3, three → 4 (Szabo's 1→4), so both triangles on an edge share its
// new vertex and no T-junction opens a hole (Szabo 2013, fig. 10a).
#include "common/reflected-vertex.glsl"
#include "common/tessellated-vertex.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 12) out;

in CornerData {
  TessellatedVertex corner;
  TessellatedVertex midpoint;
  flat int mask;
} inCorner[];

uniform int emitChildren;  // 0: unsplit triangles; 1: children of split ones

layout(xfb_buffer = 0, xfb_offset = 0) out TessellatedRecord {
  vec4 positionU;
  vec4 normalV;
  vec4 virtualFlags;
  vec4 reflectionTexelX;
  vec4 normalTexelY;
} outRecord;

void emitRecord(TessellatedVertex v) {
  outRecord.positionU = v.positionU;
  outRecord.normalV = v.normalV;
  outRecord.virtualFlags = v.virtualFlags;
  outRecord.reflectionTexelX = v.reflectionTexelX;
  outRecord.normalTexelY = v.normalTexelY;
  gl_Position = vec4(0.0);
  EmitVertex();
}

void emitTriangle(TessellatedVertex a, TessellatedVertex b, TessellatedVertex c) {
  emitRecord(a);
  emitRecord(b);
  emitRecord(c);
  EndPrimitive();
}

void main() {
  int mask = inCorner[0].mask;
  TessellatedVertex c[3] = TessellatedVertex[3](inCorner[0].corner, inCorner[1].corner, inCorner[2].corner);
  if (emitChildren == 0) {
    if (mask == 0) emitTriangle(c[0], c[1], c[2]);
    return;
  }
  if (mask == 0) return;
  TessellatedVertex m[3] = TessellatedVertex[3](inCorner[0].midpoint, inCorner[1].midpoint, inCorner[2].midpoint);
  int splitEdges = bitCount(mask);
  if (splitEdges == 3) {
    emitTriangle(c[0], m[0], m[2]);
    emitTriangle(m[0], c[1], m[1]);
    emitTriangle(m[2], m[1], c[2]);
    emitTriangle(m[0], m[1], m[2]);
  } else if (splitEdges == 1) {  // edge e split; its opposite corner joins both halves
    int e = findLSB(mask);
    emitTriangle(c[e], m[e], c[(e + 2) % 3]);
    emitTriangle(m[e], c[(e + 1) % 3], c[(e + 2) % 3]);
  } else {  // edge u kept: corner c[u + 2] is cut off, the rest is a quad cut in two
    int u = findLSB(~mask & 7), b = (u + 1) % 3, d = (u + 2) % 3;
    emitTriangle(m[b], c[d], m[d]);
    emitTriangle(c[u], c[b], m[b]);
    emitTriangle(c[u], m[b], m[d]);
  }
}
