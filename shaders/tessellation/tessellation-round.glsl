// What the kernels of a tessellation round share (tessellation-classify, -search, -decide, -emit):
// the working triangles and where their corners come from, the edge bookkeeping, the frame's
// projection and the errors of Szabo 2013, ch. 4. Each reflected object of the part is one run
// (common/tessellation-records.glsl) with its triangles in a range of the working list, as the
// previous round's layout placed them on the GPU (roundTriangle()).
#include "common/edge-split.glsl"
#include "common/reflected-vertex-buffer.glsl"
#include "common/tessellation-records.glsl"

layout(std430, binding = TESSELLATION_WORKING_BINDING) readonly buffer WorkingTriangles {
  TessellatedVertex records[];
};
// Round 0 reads the object's mesh and search slots instead: most triangles split nothing and then
// never need copying into a working list.
layout(std430, binding = TESSELLATION_MESH_VERTICES_BINDING) readonly buffer MeshVertices {
  float meshVertex[];  // scene::Vertex: position xyz, normal xyz, uv — 8 floats
};
layout(std430, binding = TESSELLATION_MESH_INDICES_BINDING) readonly buffer MeshIndices {
  uint meshIndex[];
};
layout(std430, binding = TESSELLATION_SPLITS_BINDING) buffer EdgeSplits {
  EdgeSplit splits[];
};
// Edges whose midpoint needs a search: in round 0 per run, (triangle − its first) << 2 | edge from
// 3 × its first triangle on; later for the whole part, triangle << 2 | edge.
layout(std430, binding = TESSELLATION_REQUESTS_BINDING) buffer EdgeRequests {
  uint requests[];
};
layout(std430, binding = TESSELLATION_RUNS_BINDING) buffer TessellationRuns {
  TessellationRun runs[];
};
layout(std430, binding = TESSELLATION_TOTALS_BINDING) buffer Totals {
  TessellationTotals totals;
};

uniform int fromMesh;   // 1 in round 0: corners from the mesh, not the working list
uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform uint firstSlot;
uniform uint runIndex;  // round 0: this object's run
uniform uint firstRun;  // later rounds: the part's runs, [firstRun, firstRun + runCount)
uniform uint runCount;
uniform uint parity;    // the round's work: runs[run].work[parity]
uniform int crackFree;       // 1: each edge decided alone; 0: Szabo's worst edge splits all three
uniform int pixelMetric;     // 1: error in pixels; 0: Szabo's angle error
uniform float threshold;
uniform mat4 frameWorldToClip;
uniform vec2 frameSize;

const int kAngleMetricNever = 1;  // an angle error never exceeds 1: that threshold means no split
const int kDrawable = 64;         // EdgeSplit::mask.y bit: the virtual-objects pass would draw it unsplit

// The run a working triangle of a later round belongs to: the last whose work starts at or before it
// (the layout places runs in order; a run with no triangles starts where the next one does).
uint findRun(uint triangle) {
  uint low = firstRun, high = firstRun + runCount;  // runs[low].work[parity].first <= triangle always
  while (high - low > 1u) {
    uint middle = (low + high) / 2u;
    if (runs[middle].work[parity].first <= triangle) low = middle;
    else high = middle;
  }
  return low;
}

// This invocation's working triangle, its index within its run, and the run: in round 0 one
// dispatch per run over its mesh, later one over the whole part. False past the last.
bool roundTriangle(out uint triangle, out uint local, out uint run) {
  uint id = gl_GlobalInvocationID.x;
  if (fromMesh != 0) {
    run = runIndex;
    RunWork work = runs[run].work[parity];
    local = id;
    triangle = work.first + id;
    return id < work.count;
  }
  if (id >= totals.part[parity].triangles) return false;
  triangle = id;
  run = findRun(id);
  local = id - runs[run].work[parity].first;
  return true;
}

TessellatedVertex loadCorner(uint local, uint triangle, int k) {
  if (fromMesh == 0) return records[3u * triangle + uint(k)];
  uint index = meshIndex[3u * local + uint(k)], at = 8u * index;
  vec3 position = vec3(meshVertex[at], meshVertex[at + 1u], meshVertex[at + 2u]);
  vec3 normal = vec3(meshVertex[at + 3u], meshVertex[at + 4u], meshVertex[at + 5u]);
  vec2 uv = vec2(meshVertex[at + 6u], meshVertex[at + 7u]);
  return makeTessellatedVertex((objectToWorld * vec4(position, 1.0)).xyz, normalToWorld * normal, uv, reflected[firstSlot + index]);
}

vec2 framePixel(vec3 world) {
  vec4 clip = frameWorldToClip * vec4(world, 1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * frameSize;
}

// A midpoint without a reflection point (off the G-buffer) would only cut its triangle into pieces
// the virtual-objects pass drops.
bool solved(TessellatedVertex midpoint) { return (int(midpoint.virtualFlags.w) & kReflectionUnsolved) == 0; }

// How far the rasterizer draws the edge midpoint from where its true reflection projects.
float pixelError(TessellatedVertex a, TessellatedVertex b, TessellatedVertex midpoint) {
  if (!solved(midpoint)) return 0.0;  // splitting cannot help
  return length(framePixel(midpoint.virtualFlags.xyz) - framePixel(0.5 * (a.virtualFlags.xyz + b.virtualFlags.xyz)));
}

bool exceeds(float error) { return pixelMetric != 0 || threshold < float(kAngleMetricNever) ? error >= threshold : false; }
