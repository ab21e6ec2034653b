#version 440 core
// Round step 2, per requested edge (of one object in round 0, of the whole part later): its midpoint searched by the same search as scene
// vertices, seeded between its ends' texels, and (pixel metric) its error. Runs only for the
// requests, packed, so the large search code runs at full width.
#include "search/reflection-search.glsl"
#include "common/search-statistics.glsl"
#include "tessellation/tessellation-round.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

// The edge midpoint with its reflection searched; attributes interpolated symmetrically.
TessellatedVertex searchMidpoint(TessellatedVertex a, TessellatedVertex b) {
  vec3 position = 0.5 * (a.positionU.xyz + b.positionU.xyz);
  vec3 normal = 0.5 * (a.normalV.xyz + b.normalV.xyz);
  vec2 uv = 0.5 * (vec2(a.positionU.w, a.normalV.w) + vec2(b.positionU.w, b.normalV.w));
  ivec2 seed = ivec2(round(0.5 * (vec2(a.reflectionTexelX.w, a.normalTexelY.w) + vec2(b.reflectionTexelX.w, b.normalTexelY.w))));
  ReflectedVertex reflection = searchReflection(position, seed, true, false);
  countSearch(reflection.state.z, reflection.state.w);
  return makeTessellatedVertex(position, dot(normal, normal) > 0.0 ? normalize(normal) : normal, uv, reflection);
}

void main() {
  uint id = gl_GlobalInvocationID.x, request, local, triangle;
  if (fromMesh != 0) {  // one run's requests, its mesh bound
    if (id >= runs[runIndex].requestCount) return;
    uint firstTriangle = runs[runIndex].work[parity].first;
    request = requests[3u * firstTriangle + id];
    local = request >> 2;
    triangle = firstTriangle + local;
  } else {  // the whole part's
    if (id >= totals.partRequests) return;
    request = requests[id];
    triangle = request >> 2;
    local = 0u;  // corners come from the working list
  }
  int e = int(request & 3u);
  TessellatedVertex a = loadCorner(local, triangle, e), b = loadCorner(local, triangle, (e + 1) % 3);
  TessellatedVertex midpoint = searchMidpoint(a, b);
  splits[triangle].midpoint[e] = midpoint;
  if (pixelMetric != 0) splits[triangle].error[e] = pixelError(a, b, midpoint);
}
