#version 440 core
// One round of adaptive tessellation (Szabo 2013, ch. 4), per working triangle: the error of each
// edge, which edges split, and the reflection of each new edge midpoint, found by the same search
// as scene vertices, seeded between its endpoints' texels.
layout(local_size_x = 64) in;

#include "common/search-core.glsl"
#include "common/search-statistics.glsl"
#include "common/edge-split.glsl"
#include "common/reflected-vertex-buffer.glsl"

layout(std430, binding = 3) readonly buffer WorkingTriangles {
  TessellatedVertex records[];
};
// Round 0 reads the object's mesh and search slots instead: most triangles split nothing and then
// never need copying into a working list.
layout(std430, binding = 0) readonly buffer MeshVertices {
  float meshVertex[];  // scene::Vertex: position xyz, normal xyz, uv — 8 floats
};
layout(std430, binding = 6) readonly buffer MeshIndices {
  uint meshIndex[];
};
layout(std430, binding = 4) writeonly buffer EdgeSplits {
  EdgeSplit splits[];
};
layout(std430, binding = 5) buffer TessellationCounters {
  uint counters[];  // per object of the round: triangles the split ones become, triangles finished
};

uniform int fromMesh;        // 1 in round 0: corners from the mesh below, not the working list
uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform uint firstSlot;
uniform uint firstTriangle;  // this object's triangles in the working list
uniform uint triangleCount;
uniform uint counterIndex;   // this object's pair of counters
uniform int crackFree;          // 1: each edge decided alone; 0: Szabo's worst edge splits all three
uniform int pixelMetric;        // 1: error in pixels; 0: Szabo's angle error
uniform float threshold;
uniform mat4 gbufferWorldToClip;
uniform mat4 frameWorldToClip;
uniform vec2 frameSize;
uniform vec4 mirrorRect;  // the mirror's bounds on screen in frame pixels: low x, y, high x, y
uniform vec4 mirrorSphere;  // the mirror's bounding sphere in world space: centre, radius

// With the pixel metric, an edge longer than this share of its distance from the mirror (at least
// the mirror's radius) splits whatever its midpoint shows: the reflection of a large triangle near a mirror bends inside
// it, where no edge midpoint sees it (a table top under a bowl reflects all round the bowl's foot,
// while its corners reflect near the rim).
const float kMaxEdgeAngle = 0.5;

const int kAngleMetricNever = 1;  // an angle error never exceeds 1: that threshold means no split

// Szabo's edge error: 1 − (N·b + 1)/2 with N the mirror normal at the midpoint of the two
// reflection points and b the bisector there towards the eye and the midpoint of the edge.
// Symmetric in its endpoints, so both triangles on an edge decide it alike.
float angleError(TessellatedVertex a, TessellatedVertex b) {
  vec4 clip = gbufferWorldToClip * vec4(0.5 * (a.reflectionTexelX.xyz + b.reflectionTexelX.xyz), 1.0);
  if (clip.w <= 0.0) return 0.0;
  ivec2 size = textureSize(gbufferPosition, 0).xy;
  ivec2 texel = ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * vec2(size)));
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return 0.0;
  vec4 surface = texelFetch(gbufferPosition, ivec3(texel, layer), 0);
  if (surface.w <= 0.0) return 0.0;  // off the mirror: nothing there to draw finer
  vec3 normal = normalize(texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz);
  vec3 edgeMidpoint = 0.5 * (a.positionU.xyz + b.positionU.xyz);
  vec3 bisector = normalize(normalize(eyePosition - surface.xyz) + normalize(edgeMidpoint - surface.xyz));
  return 1.0 - (dot(normal, bisector) + 1.0) * 0.5;
}

vec2 framePixel(vec3 world) {
  vec4 clip = frameWorldToClip * vec4(world, 1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * frameSize;
}

// Whether the triangle's virtual corners all lie beyond one side of the mirror's rectangle on
// screen (frame pixels); a triangle crossing it may still show inside.
bool outsideMirrorRect(TessellatedVertex a, TessellatedVertex b, TessellatedVertex c) {
  vec2 pa = framePixel(a.virtualFlags.xyz), pb = framePixel(b.virtualFlags.xyz), pc = framePixel(c.virtualFlags.xyz);
  vec2 low = min(pa, min(pb, pc)), high = max(pa, max(pb, pc));
  return any(lessThan(high, mirrorRect.xy)) || any(greaterThan(low, mirrorRect.zw));
}

// A midpoint without a reflection point (off the G-buffer) would only cut its triangle into pieces
// the virtual-objects pass drops.
bool solved(TessellatedVertex midpoint) { return (int(midpoint.virtualFlags.w) & kReflectionUnsolved) == 0; }

// How far the rasterizer draws the edge midpoint from where its true reflection projects.
float pixelError(TessellatedVertex a, TessellatedVertex b, TessellatedVertex midpoint) {
  if (!solved(midpoint)) return 0.0;  // splitting cannot help
  return length(framePixel(midpoint.virtualFlags.xyz) - framePixel(0.5 * (a.virtualFlags.xyz + b.virtualFlags.xyz)));
}

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

bool nearMirror(TessellatedVertex a, TessellatedVertex b) {
  if (pixelMetric == 0) return false;  // Szabo's angle metric is kept as the paper has it
  vec3 midpoint = 0.5 * (a.positionU.xyz + b.positionU.xyz);
  float reach = max(length(midpoint - mirrorSphere.xyz), mirrorSphere.w);
  return length(a.positionU.xyz - b.positionU.xyz) > kMaxEdgeAngle * reach;
}

bool exceeds(float error) { return pixelMetric != 0 || threshold < float(kAngleMetricNever) ? error >= threshold : false; }

TessellatedVertex loadCorner(uint local, uint triangle, int k) {
  if (fromMesh == 0) return records[3u * triangle + uint(k)];
  uint index = meshIndex[3u * local + uint(k)], at = 8u * index;
  vec3 position = vec3(meshVertex[at], meshVertex[at + 1u], meshVertex[at + 2u]);
  vec3 normal = vec3(meshVertex[at + 3u], meshVertex[at + 4u], meshVertex[at + 5u]);
  vec2 uv = vec2(meshVertex[at + 6u], meshVertex[at + 7u]);
  return makeTessellatedVertex((objectToWorld * vec4(position, 1.0)).xyz, normalToWorld * normal, uv, reflected[firstSlot + index]);
}

void main() {
  if (gl_GlobalInvocationID.x >= triangleCount) return;
  uint triangle = firstTriangle + gl_GlobalInvocationID.x;
  uint local = gl_GlobalInvocationID.x;
  TessellatedVertex corner[3] = TessellatedVertex[3](loadCorner(local, triangle, 0), loadCorner(local, triangle, 1), loadCorner(local, triangle, 2));
  int flags0 = int(corner[0].virtualFlags.w), flags1 = int(corner[1].virtualFlags.w), flags2 = int(corner[2].virtualFlags.w);
  bool near[3] = bool[3](nearMirror(corner[0], corner[1]), nearMirror(corner[1], corner[2]), nearMirror(corner[2], corner[0]));
  bool anyNear = near[0] || near[1] || near[2];
  // The virtual-objects pass drops these whatever their size, and a virtual triangle wholly
  // outside the frame or the mirror's part of it is not seen: nothing to refine, unless full
  // tessellation (threshold 0) was asked for. Corners hidden behind a convex part hide the whole
  // triangle (region C is convex); on a concave part, where it need not be, splitting such
  // triangles cost a third more triangles in the kitchen and changed no pixel. A large triangle near
  // the mirror may still show between corners whose images lie off the mirror's rectangle.
  bool dropped = ((flags0 | flags1 | flags2) & kReflectionUnsolved) != 0 ||
                 (flags0 & flags1 & flags2 & kReflectionHidden) != 0 ||
                 (!anyNear && outsideMirrorRect(corner[0], corner[1], corner[2]));

  // Which edges need their midpoint searched: every drawn edge longer than the pixel threshold
  // (its error depends on the search), or every edge the angle metric splits.
  bool search[3] = bool[3](false, false, false);
  float error[3] = float[3](0.0, 0.0, 0.0);
  int mask = 0;
  if (!dropped || threshold == 0.0) {
    for (int e = 0; e < 3; ++e) {
      TessellatedVertex a = corner[e], b = corner[(e + 1) % 3];
      if (pixelMetric != 0)  // crack-free: an edge drawn shorter than the threshold cannot bend by more than it
        search[e] = crackFree == 0 || threshold == 0.0 || near[e] ||
                    length(framePixel(a.virtualFlags.xyz) - framePixel(b.virtualFlags.xyz)) >= threshold;
      else
        error[e] = angleError(a, b);
    }
    if (pixelMetric == 0) {
      float worst = max(error[0], max(error[1], error[2]));
      for (int e = 0; e < 3; ++e)
        if (crackFree != 0 ? exceeds(error[e]) : exceeds(worst)) search[e] = true;
    }
  }
  // One call site for the search, which is large.
  EdgeSplit split;
  for (int e = 0; e < 3; ++e) {
    if (!search[e]) continue;
    split.midpoint[e] = searchMidpoint(corner[e], corner[(e + 1) % 3]);
    if (pixelMetric != 0) error[e] = pixelError(corner[e], corner[(e + 1) % 3], split.midpoint[e]);
  }
  if (pixelMetric != 0) {
    float worst = max(error[0], max(error[1], error[2]));
    for (int e = 0; e < 3; ++e)
      if (search[e] && (crackFree != 0 ? exceeds(error[e]) || near[e] : exceeds(worst) || anyNear) && solved(split.midpoint[e]))
        mask |= 1 << e;
  } else {
    for (int e = 0; e < 3; ++e)
      if (search[e]) mask |= 1 << e;
  }
  // Most triangles split nothing: write their mask alone, not 256 bytes of midpoints.
  splits[triangle].mask = ivec4(mask, 0, 0, 0);
  for (int e = 0; e < 3; ++e)
    if ((mask & (1 << e)) != 0) splits[triangle].midpoint[e] = split.midpoint[e];
  const uint kChildren[4] = uint[4](0u, 2u, 3u, 4u);  // by number of split edges
  if (mask == 0) atomicAdd(counters[2u * counterIndex + 1u], 1u);
  else atomicAdd(counters[2u * counterIndex], kChildren[bitCount(mask)]);
}
