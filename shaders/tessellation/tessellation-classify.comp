#version 440 core
// Round step 1 of adaptive tessellation (Szabo 2013, ch. 4), per working triangle: which edges need
// their midpoint searched to be decided, listed for tessellation-search; Szabo's angle error, which
// needs no search, is measured here. Carries no search code, so the many triangles that split
// nothing cost little.
#include "common/reflectable-triangle.glsl"
#include "search/reflection-search.glsl"
#include "tessellation/tessellation-round.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

uniform vec4 mirrorRect;    // the mirror's bounds on screen in frame pixels: low x, y, high x, y
uniform vec4 mirrorSphere;  // the mirror's bounding sphere in world space: centre, radius
uniform int everyCornerReflected;  // 1 on concave and saddle parts (common/reflectable-triangle.glsl)

// With the pixel metric, an edge longer than this share of its distance from the mirror (at least
// the mirror's radius) splits whatever its midpoint shows: the reflection of a large triangle near a
// mirror bends inside it, where no edge midpoint sees it (a table top under a bowl reflects all round
// the bowl's foot, while its corners reflect near the rim).
const float kMaxEdgeAngle = 0.5;

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

// Whether the triangle's virtual corners all lie beyond one side of the mirror's rectangle on
// screen (frame pixels); a triangle crossing it may still show inside.
bool outsideMirrorRect(TessellatedVertex a, TessellatedVertex b, TessellatedVertex c) {
  vec2 pa = framePixel(a.virtualFlags.xyz), pb = framePixel(b.virtualFlags.xyz), pc = framePixel(c.virtualFlags.xyz);
  vec2 low = min(pa, min(pb, pc)), high = max(pa, max(pb, pc));
  return any(lessThan(high, mirrorRect.xy)) || any(greaterThan(low, mirrorRect.zw));
}

bool nearMirror(TessellatedVertex a, TessellatedVertex b) {
  if (pixelMetric == 0) return false;  // Szabo's angle metric is kept as the paper has it
  vec3 midpoint = 0.5 * (a.positionU.xyz + b.positionU.xyz);
  float reach = max(length(midpoint - mirrorSphere.xyz), mirrorSphere.w);
  return length(a.positionU.xyz - b.positionU.xyz) > kMaxEdgeAngle * reach;
}

void main() {
  uint triangle, local, run;
  if (!roundTriangle(triangle, local, run)) return;
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
  vec3 error = vec3(0.0);
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
  // Whether the virtual-objects pass would draw the triangle unsplit: one it would drop is not
  // written to the finished list at all.
  bool drawable = reflectableTriangle(corner, everyCornerReflected != 0);
  int requested = 0, nearBits = 0;
  for (int e = 0; e < 3; ++e) {
    if (near[e]) nearBits |= 1 << e;
    if (!search[e]) continue;
    requested |= 1 << e;
    if (fromMesh != 0) requests[3u * (triangle - local) + atomicAdd(runs[run].requestCount, 1u)] = (local << 2) | uint(e);
    else requests[atomicAdd(totals.partRequests, 1u)] = (triangle << 2) | uint(e);
  }
  splits[triangle].mask = ivec4(0, requested | (nearBits << 3) | (drawable ? kDrawable : 0), 0, 0);
  splits[triangle].error = vec4(error, 0.0);
}
