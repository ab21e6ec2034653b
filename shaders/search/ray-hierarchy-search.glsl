// Szabo's (2013, ch. 4) ray-hierarchy search: the texel whose reflected-ray cone holds the vertex,
// then the crosshair climb to the best texel nearby.
#include "common/ray-hierarchy.glsl"
#include "search/crosshair.glsl"

uniform int rayHierarchy;                   // 1: the texel comes from the ray hierarchy, not a climb
uniform sampler2DArray rayHierarchySpheres;  // built by ray-hierarchy/ for this frame's eye
uniform sampler2DArray rayHierarchyCones;
uniform int rayHierarchyTop;                // its coarsest level, one texel

const float kNoCone = 1e9;
const int kRayHierarchyStack = 48;
const int kMaxRayHierarchyVisits = 1024;  // nodes per traversal: past it the vertex counts as in no cone
// Szabo's enlargement, applied again per retry when the vertex lies in no cone: half-angles ×1.5, radii ×2.
const float kConeEnlargement = 1.5, kSphereEnlargement = 2.0;
const int kEnlargements = 2;

ivec2 rayHierarchySize(int level) { return mipLevelSize(textureSize(rayHierarchySpheres, 0).xy, level); }

// How far (radians) the vertex lies outside the cone of a node whose apex may be anywhere in the
// node's sphere (Szabo's cone–sphere test, Roger et al.); at most 0 inside, kNoCone off the mirror.
float coneExcess(ivec2 texel, int level, float coneScale, float sphereScale) {
  vec4 sphere = texelFetch(rayHierarchySpheres, ivec3(texel, layer), level);
  if (sphere.w < 0.0) return kNoCone;
  vec4 cone = texelFetch(rayHierarchyCones, ivec3(texel, layer), level);
  vec3 toVertex = vertexWorld - sphere.xyz;
  float distance = length(toVertex), radius = sphere.w * sphereScale;
  if (distance <= radius) return -3.2;  // inside the sphere: every direction is possible
  return angleBetween(toVertex / distance, cone.xyz) - cone.w * coneScale - asin(radius / distance);
}

// Szabo's traversal: depth first from the top, into every child whose (scaled) cone holds the
// vertex, the one it lies deepest in first; among the leaves that hold it, the one whose reflection
// is best (N·B) wins, his closest reflected ray. Cones are conservative, so several leaves can hold
// a vertex (a silhouette's leaves hold everything behind it); stopping at the first would pick one
// far from the answer. Each node visited (a window of up to 3×3 children) is a step; past
// kMaxRayHierarchyVisits the best so far stands. False when no leaf holds the vertex.
bool traverseRayHierarchy(float coneScale, float sphereScale, inout int steps, out ivec2 best, out float value) {
  ivec3 stack[kRayHierarchyStack];
  int depth = 0;
  stack[depth++] = ivec3(0, 0, rayHierarchyTop);
  best = ivec2(0);
  value = kInvalid;
  bool held = false;
  for (int visits = 0; depth > 0 && visits < kMaxRayHierarchyVisits; ++visits) {
    ivec3 node = stack[--depth];
    ++steps;
    if (node.z == 0) {  // a one-texel mirror's G-buffer: the top is a leaf
      best = node.xy;
      value = objectiveAt(best, 0);
      return coneExcess(node.xy, 0, coneScale, sphereScale) <= 0.0;
    }
    ivec2 low, high;
    rayHierarchyChildren(node.xy, rayHierarchySize(node.z), rayHierarchySize(node.z - 1), low, high);
    ivec2 children[9];
    float childExcess[9];
    int count = 0;
    for (int y = low.y; y <= high.y; ++y) {
      for (int x = low.x; x <= high.x; ++x) {
        float excess = coneExcess(ivec2(x, y), node.z - 1, coneScale, sphereScale);
        if (excess > 0.0) continue;
        if (node.z == 1) {  // a leaf that holds the vertex: a candidate
          held = true;
          float candidate = objectiveAt(ivec2(x, y), 0);
          if (candidate > value) {
            value = candidate;
            best = ivec2(x, y);
          }
          continue;
        }
        int k = count++;
        for (; k > 0 && childExcess[k - 1] > excess; --k) {
          children[k] = children[k - 1];
          childExcess[k] = childExcess[k - 1];
        }
        children[k] = ivec2(x, y);
        childExcess[k] = excess;
      }
    }
    // Deepest-held child on top; what does not fit is dropped, worst first.
    for (int k = min(count, kRayHierarchyStack - depth) - 1; k >= 0; --k) stack[depth++] = ivec3(children[k], node.z - 1);
  }
  return held;
}

// The leaf down the path of least cone excess: where a vertex in no cone (hidden behind the mirror's
// silhouette, or reflected by no texel of this part) is nearest to being reflected.
ivec2 nearestConePath(inout int steps) {
  ivec2 node = ivec2(0);
  for (int level = rayHierarchyTop; level > 0; --level) {
    ++steps;
    ivec2 low, high;
    rayHierarchyChildren(node, rayHierarchySize(level), rayHierarchySize(level - 1), low, high);
    float least = kNoCone;
    ivec2 next = low;
    for (int y = low.y; y <= high.y; ++y) {
      for (int x = low.x; x <= high.x; ++x) {
        float excess = coneExcess(ivec2(x, y), level - 1, 1.0, 1.0);
        if (excess < least) {
          least = excess;
          next = ivec2(x, y);
        }
      }
    }
    node = next;
  }
  return node;
}

// The texel of the vertex's reflection by the ray hierarchy, `value` its N·B (kInvalid: the mirror
// covers no texel). A vertex in no cone is searched again with Szabo's enlarged cones, and a vertex
// in none of those either takes the nearest cone's path. The texel found then climbs to the best
// texel nearby: a leaf's cone is wider than its texel, so the best holding leaf can be a neighbour
// of the best texel (Szabo's jitter at grazing angles), and the refinement below needs the best.
// `knownHidden`: region C already decided exactly (no cone can hold it).
ivec2 rayHierarchySearch(bool knownHidden, inout int steps, inout int flags, out float value) {
  value = kInvalid;
  if (texelFetch(rayHierarchySpheres, ivec3(0, 0, layer), rayHierarchyTop).w < 0.0) return ivec2(0);
  ivec2 texel = ivec2(0);
  float coneScale = 1.0, sphereScale = 1.0;
  bool held = false;
  for (int attempt = 0; attempt <= kEnlargements && !knownHidden; ++attempt) {
    held = traverseRayHierarchy(coneScale, sphereScale, steps, texel, value);
    if (held) break;
    flags |= kReflectionEnlarged;
    coneScale *= kConeEnlargement;
    sphereScale *= kSphereEnlargement;
  }
  if (!held) {
    flags |= kReflectionInNoCone;
    texel = nearestConePath(steps);
  }
  return climb(texel, 0, maxWalkSteps, steps, value);
}
