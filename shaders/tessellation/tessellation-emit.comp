#version 440 core
// Round step 5, per working triangle: writes the round's output, the unsplit triangle
// to the finished list and the split one's children to the next working list, each at a place in
// the run's share that the layout gave it. Crack-free patterns by number of split edges: one → 2
// triangles, two → 3, three → 4 (Szabo's 1→4), so both triangles on an edge share its new vertex
// and no T-junction opens a hole (Szabo 2013, fig. 10a). Szabo emits with a geometry shader and
// transform feedback; on a CPU rasterizer that cost 125-145 ms a frame in the kitchen, ufo and ants
// scenes, a compute kernel a fraction of it.
#include "tessellation/tessellation-round.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

layout(std430, binding = TESSELLATION_FINISHED_BINDING) writeonly buffer FinishedTriangles {
  TessellatedVertex finished[];
};
layout(std430, binding = TESSELLATION_NEXT_WORKING_BINDING) writeonly buffer NextWorkingTriangles {
  TessellatedVertex next[];
};

void writeFinished(uint run, TessellatedVertex a, TessellatedVertex b, TessellatedVertex c) {
  uint at = 3u * (runs[run].finishedBase + atomicAdd(runs[run].finishedPlaced, 1u));
  finished[at] = a;
  finished[at + 1u] = b;
  finished[at + 2u] = c;
}

void writeChild(uint run, uint child, TessellatedVertex a, TessellatedVertex b, TessellatedVertex c) {
  uint at = 3u * (runs[run].childrenBase + child);
  next[at] = a;
  next[at + 1u] = b;
  next[at + 2u] = c;
}

void main() {
  uint triangle, local, run;
  if (!roundTriangle(triangle, local, run) || runs[run].drawnFromMesh != 0) return;
  TessellatedVertex c[3] = TessellatedVertex[3](loadCorner(local, triangle, 0), loadCorner(local, triangle, 1), loadCorner(local, triangle, 2));
  bool finishAll = runs[run].finishAll != 0;
  int mask = finishAll ? 0 : splits[triangle].mask.x;
  if (mask == 0) {
    // Undrawable ones are left out, as decide counted them; the last round, which decided nothing,
    // writes every triangle.
    if (finishAll || (splits[triangle].mask.y & kDrawable) != 0) writeFinished(run, c[0], c[1], c[2]);
    return;
  }
  TessellatedVertex m[3] = TessellatedVertex[3](splits[triangle].midpoint[0], splits[triangle].midpoint[1], splits[triangle].midpoint[2]);
  const uint kChildren[4] = uint[4](0u, 2u, 3u, 4u);  // by number of split edges
  uint child = atomicAdd(runs[run].childrenPlaced, kChildren[bitCount(mask)]);
  int splitEdges = bitCount(mask);
  if (splitEdges == 3) {
    writeChild(run, child, c[0], m[0], m[2]);
    writeChild(run, child + 1u, m[0], c[1], m[1]);
    writeChild(run, child + 2u, m[2], m[1], c[2]);
    writeChild(run, child + 3u, m[0], m[1], m[2]);
  } else if (splitEdges == 1) {  // edge e split; its opposite corner joins both halves
    int e = findLSB(mask);
    writeChild(run, child, c[e], m[e], c[(e + 2) % 3]);
    writeChild(run, child + 1u, m[e], c[(e + 1) % 3], c[(e + 2) % 3]);
  } else {  // edge u kept: corner c[u + 2] is cut off, the rest is a quad cut in two
    int u = findLSB(~mask & 7), b = (u + 1) % 3, d = (u + 2) % 3;
    writeChild(run, child, m[b], c[d], m[d]);
    writeChild(run, child + 1u, c[u], c[b], m[b]);
    writeChild(run, child + 2u, c[u], m[b], m[d]);
  }
}
