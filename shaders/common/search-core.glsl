// The reflection-point search for one vertex: find the mirror texel, by Estalella et al.'s (2006)
// crosshair search (hill-climb N·B over the mirror's G-buffer in 3×3 windows from a seed texel when it
// is on the mirror, else coarse-to-fine down the G-buffer pyramid) or by Szabo's (2013) ray
// hierarchy; then refine below the texel. Or no search: Ofek & Rappoport's (1998) explosion-map
// look-ups, optionally refined by the crosshair search from the point they give. Or, on a mirror
// declared as a linear extrusion, their exact 2-D reduction (common/extrusion.glsl). Shared by the search
// of scene vertices (search/search.comp) and of the vertices adaptive tessellation adds (tessellation/).
#include "common/explosion-map.glsl"
#include "common/extrusion.glsl"
#include "common/quadric.glsl"
#include "common/ray-hierarchy.glsl"
#include "common/reflection.glsl"
#include "common/reflected-vertex.glsl"

uniform sampler2DArray gbufferPosition;  // w > 0 on mirror texels
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform int coarseLevel;       // pyramid level scanned exhaustively on a cold start
uniform ivec4 coarseRect;      // the texels of that level the mirror covers: low x, y, high x, y (exclusive)
uniform vec3 eyePosition;
uniform int maxWalkSteps;

const float kInvalid = -3.0;   // below any reflectionObjective
const float kContactHeight = 1e-3;  // unit-sphere radii: closer vertices reflect from their foot point
const float kStalledResidual = 0.1;  // normal and bisector still this far apart (sine): the refinement is lost
// On a mesh the best point of a part whose reflection lies beyond its outline (hidden behind a
// convex part's silhouette, or on another part) stops on the outline with normal and bisector this
// far apart (sine), or as far as the normal turns from one texel to the next on a mirror a few texels
// wide: such a vertex has no reflection point in the part.
const float kNoReflectionResidual = 0.05;
// Where the G-buffer holds the exact surface (a parametric mirror's patches), Newton's method on the
// patch decides where it converges (refineOnPatch); where it does not, more is asked than of a mesh:
// normal and bisector within kOutlineResidual, or, held on the outline, half the normal's turn to
// its smoothest neighbour texel if that is more (a reflection point inside the outline texel is that
// close to its centre's). The thin spout and handle turn their normals by tenths a texel, which the
// mesh rule's whole turn let pass for points 50 px from any reflection.
const float kOutlineResidual = 0.01;
uniform int exactGBuffer;

const ivec2 kNeighbours[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),  // crosshair first
                                      ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));

vec3 vertexWorld;

// GL mip sizes: halved, rounded down, at least 1. Not textureSize(sampler, level): with a level that
// differs between invocations it returned wrong sizes on llvmpipe (the ray hierarchy lost its way).
ivec2 mipLevelSize(ivec2 base, int level) { return max(base >> level, ivec2(1)); }

float objectiveAt(ivec2 texel, int level) {
  ivec2 size = mipLevelSize(textureSize(gbufferPosition, 0).xy, level);
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return kInvalid;
  vec4 p = texelFetch(gbufferPosition, ivec3(texel, layer), level);
  if (p.w <= 0.0) return kInvalid;
  return reflectionObjective(p.xyz, texelFetch(gbufferNormal, ivec3(texel, layer), level).xyz, eyePosition,
                             vertexWorld);
}

// Moves to the best of the 3×3 window until the centre is best; each window examined is a step.
ivec2 climb(ivec2 texel, int level, int stepLimit, inout int steps, out float value) {
  value = objectiveAt(texel, level);
  for (int i = 0; i < stepLimit; ++i) {
    ++steps;
    ivec2 next = texel;
    float nextValue = value;
    for (int k = 0; k < 8; ++k) {
      float candidate = objectiveAt(texel + kNeighbours[k], level);
      if (candidate > nextValue) {
        nextValue = candidate;
        next = texel + kNeighbours[k];
      }
    }
    if (next == texel) break;
    texel = next;
    value = nextValue;
  }
  return texel;
}

// Exhaustive scan of the mirror's texels at the coarse level, keeping the best few coarse texels
// that are not neighbours (a part whose normals wrap, like a bowl's outside with its rim, has more
// than one local best: averaged coarse normals can rank the wrong one first), then one climb per
// finer level from each; the best at level 0 wins. The level is the one where the mirror spans at
// most 8 texels (16 on other mirrors than closed convex ones), so a small mirror is still seen in
// parts whose normals differ.
const int kMaxColdCandidates = 3;
uniform int coldCandidates;  // 1 on a closed convex mirror (one best), kMaxColdCandidates otherwise

ivec2 coldSearch(inout int steps, out float value) {
  ivec2 candidate[kMaxColdCandidates];
  float candidateValue[kMaxColdCandidates];
  for (int k = 0; k < kMaxColdCandidates; ++k) {
    candidate[k] = coarseRect.xy;
    candidateValue[k] = kInvalid;
  }
  for (int y = coarseRect.y; y < coarseRect.w; ++y) {
    for (int x = coarseRect.x; x < coarseRect.z; ++x) {
      float v = objectiveAt(ivec2(x, y), coarseLevel);
      if (v <= candidateValue[coldCandidates - 1]) continue;
      // Replace a kept neighbour it beats, else the worst kept; then restore the order.
      int slot = coldCandidates - 1;
      bool beaten = false;
      for (int k = 0; k < coldCandidates; ++k) {
        ivec2 apart = abs(candidate[k] - ivec2(x, y));
        if (candidateValue[k] > kInvalid && max(apart.x, apart.y) <= 2) {
          slot = k;
          beaten = v <= candidateValue[k];
          break;
        }
      }
      if (beaten) continue;
      candidate[slot] = ivec2(x, y);
      candidateValue[slot] = v;
      for (int k = slot; k > 0 && candidateValue[k] > candidateValue[k - 1]; --k) {
        ivec2 t = candidate[k];
        candidate[k] = candidate[k - 1];
        candidate[k - 1] = t;
        float tv = candidateValue[k];
        candidateValue[k] = candidateValue[k - 1];
        candidateValue[k - 1] = tv;
      }
    }
  }
  steps += ((coarseRect.z - coarseRect.x) * (coarseRect.w - coarseRect.y) + 8) / 9;  // in 3×3 windows, like climb steps
  ivec2 best = candidate[0];
  value = kInvalid;
  for (int k = 0; k < coldCandidates; ++k) {
    if (candidateValue[k] <= kInvalid) break;
    ivec2 texel = candidate[k];
    float reached = candidateValue[k];
    for (int level = coarseLevel - 1; level >= 0; --level) texel = climb(texel * 2, level, maxWalkSteps, steps, reached);
    if (reached > value) {
      value = reached;
      best = texel;
    }
  }
  return best;
}

// ---- Ray-hierarchy search (Szabo 2013, ch. 4) ----
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

// Bilinear surface between texel centres (texel i's centre at coordinate i); false off the mirror.
// Corners with no weight are not needed; one missing corner is completed as a parallelogram from
// the other three, so refinement reaches the silhouette, where grazing reflection points live.
bool surfaceAt(vec2 coordinate, out vec3 position, out vec3 normal) {
  ivec2 base = ivec2(floor(coordinate));
  vec2 f = coordinate - vec2(base);
  const ivec2 corner[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));
  float weight[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  vec3 p[4], n[4];
  bool present[4];
  int missing = -1;
  for (int i = 0; i < 4; ++i) {
    ivec2 at = base + corner[i];
    vec4 texel = texelFetch(gbufferPosition, ivec3(at, layer), 0);
    present[i] = texel.w > 0.0 && all(lessThan(at, textureSize(gbufferPosition, 0).xy)) && all(greaterThanEqual(at, ivec2(0)));
    p[i] = present[i] ? texel.xyz : vec3(0.0);
    n[i] = present[i] ? texelFetch(gbufferNormal, ivec3(at, layer), 0).xyz : vec3(0.0);
    if (present[i] || weight[i] == 0.0) continue;
    if (missing >= 0) return false;
    missing = i;
  }
  if (missing >= 0) {  // the corner opposite the missing one is shared by both its neighbours
    int opposite = 3 - missing, a = missing ^ 1, b = missing ^ 2;
    if (!present[opposite] || !present[a] || !present[b]) return false;
    p[missing] = p[a] + p[b] - p[opposite];
    n[missing] = n[a] + n[b] - n[opposite];
  }
  position = weight[0] * p[0] + weight[1] * p[1] + weight[2] * p[2] + weight[3] * p[3];
  normal = normalize(weight[0] * n[0] + weight[1] * n[1] + weight[2] * n[2] + weight[3] * n[3]);
  return true;
}

// Tangential part of the bisector: zero at the reflection point. Unlike 1 − N·B it keeps full
// float precision near the solution, so it can drive a Gauss–Newton step.
vec3 tangentialBisector(vec3 position, vec3 normal) {
  vec3 b = normalize(normalize(eyePosition - position) + normalize(vertexWorld - position));
  return b - dot(b, normal) * normal;
}

bool residualAt(vec2 coordinate, out vec3 residual) {
  vec3 p, n;
  if (!surfaceAt(coordinate, p, n)) return false;
  residual = tangentialBisector(p, n);
  return true;
}

// Derivative of the residual per texel along `axis`: central where both sides are on the mirror,
// one-sided at the silhouette.
bool residualSlope(vec2 x, vec3 r0, vec2 axis, out vec3 slope) {
  vec3 plus, minus;
  bool hasPlus = residualAt(x + 0.5 * axis, plus), hasMinus = residualAt(x - 0.5 * axis, minus);
  if (hasPlus && hasMinus) slope = plus - minus;
  else if (hasPlus) slope = 2.0 * (plus - r0);
  else if (hasMinus) slope = 2.0 * (r0 - minus);
  return hasPlus || hasMinus;
}

// Up to three Gauss–Newton steps on the bilinear surface, staying within 2.5 texels of the climb's
// winner. `blocked`: a step would have left the mirror (part): the best point lies on its outline,
// where a vertex without a reflection point in the part ends up.
vec2 refine(ivec2 texel, out bool blocked) {
  vec2 x = vec2(texel);
  blocked = false;
  for (int iteration = 0; iteration < 3; ++iteration) {
    vec3 r0, jx, jy;
    if (!residualAt(x, r0) || !residualSlope(x, r0, vec2(1.0, 0.0), jx) || !residualSlope(x, r0, vec2(0.0, 1.0), jy)) {
      blocked = true;
      break;
    }
    mat2 normalMatrix = mat2(dot(jx, jx), dot(jx, jy), dot(jx, jy), dot(jy, jy));
    if (abs(determinant(normalMatrix)) < 1e-30) break;
    vec2 step = -inverse(normalMatrix) * vec2(dot(jx, r0), dot(jy, r0));
    if (length(step) > 1.0) step = normalize(step);
    vec2 next = clamp(x + step, vec2(texel) - 2.5, vec2(texel) + 2.5);
    vec3 unused;
    if (!residualAt(next, unused)) {
      blocked = true;
      break;
    }
    x = next;
    if (length(step) < 1e-3) break;  // converged within a thousandth of a texel
  }
  return x;
}

vec3 tangentialBisectorOnQuadric(vec3 unitPoint) {
  vec3 p, n;
  quadricSurface(unitPoint, p, n);
  return tangentialBisector(p, n);
}

// Gauss–Newton on the exact surface of an analytic mirror, from the climb's texel, in coordinates
// of the unit sphere's tangent plane at the current point: unlike G-buffer coordinates they stay
// well conditioned up to the silhouette, where one texel spans a wide arc of the surface and the
// bilinear surface strays from the true one.
// Returns false when it is lost: far from any reflection point (a start on the wrong side).
bool refineOnQuadric(vec3 start, out vec3 position, out vec3 normal) {
  vec3 unitVertex = toUnitSpace(vertexWorld);
  // A vertex touching the mirror (or on or in it) reflects from within its height of its foot
  // point, where the residual turns too fast for float derivatives: take the foot point.
  if (length(unitVertex) - 1.0 < kContactHeight) {
    quadricSurface(normalize(unitVertex), position, normal);
    return true;
  }
  vec3 unitEye = toUnitSpace(eyePosition);
  // Central-difference step, radians on the unit sphere: below the vertex's height above the
  // surface, over which the residual turns when the vertex nearly touches the mirror.
  float h = clamp(0.25 * (length(toUnitSpace(vertexWorld)) - 1.0), 1e-5, 1e-3);
  vec3 u = normalize(toUnitSpace(start));
  for (int iteration = 0; iteration < 24; ++iteration) {  // a texel of a small mirror spans a wide arc
    vec3 t1 = normalize(cross(u, abs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(u, t1);
    vec3 r0 = tangentialBisectorOnQuadric(u);
    vec3 jx = (tangentialBisectorOnQuadric(normalize(u + h * t1)) - tangentialBisectorOnQuadric(normalize(u - h * t1))) / (2.0 * h);
    vec3 jy = (tangentialBisectorOnQuadric(normalize(u + h * t2)) - tangentialBisectorOnQuadric(normalize(u - h * t2))) / (2.0 * h);
    mat2 normalMatrix = mat2(dot(jx, jx), dot(jx, jy), dot(jx, jy), dot(jy, jy));
    if (abs(determinant(normalMatrix)) < 1e-30) break;
    vec2 step = -inverse(normalMatrix) * vec2(dot(jx, r0), dot(jy, r0));
    if (length(step) > 0.25) step = 0.25 * normalize(step);
    // Backtracking: halve the step until it stays visible and lowers the residual, which turns
    // sharply when the vertex nearly touches the mirror and full steps would overshoot. Steps under
    // 0.03 rad are trusted: near grazing points the residual does not fall monotonically along them,
    // and testing them stopped convergence early.
    vec3 next = normalize(u + step.x * t1 + step.y * t2);
    int halving = 0;
    for (; halving < 12; ++halving) {
      if (facesEye(next, unitEye)) {
        vec3 r1 = tangentialBisectorOnQuadric(next);
        if (dot(r1, r1) < dot(r0, r0) || length(step) < 0.03) break;
      }
      step *= 0.5;
      next = normalize(u + step.x * t1 + step.y * t2);
    }
    if (halving == 12) break;
    u = next;
    if (length(step) < 1e-6) break;  // converged to float precision
  }
  quadricSurface(u, position, normal);
  return length(tangentialBisectorOnQuadric(u)) < kStalledResidual;
}

// How far the G-buffer normal turns from the texel to its neighbours on the mirror: to the
// steepest, or to the smoothest (`smoothest`: then a crease, where the normal jumps across and no
// reflection point lies, does not count). 0 for a lone texel.
float normalTurnPerTexel(ivec2 texel, bool smoothest) {
  vec3 n0 = texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz;
  float steepest = 0.0, least = 2.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 at = texel + kNeighbours[k];
    if (objectiveAt(at, 0) <= kInvalid) continue;
    float turn = length(texelFetch(gbufferNormal, ivec3(at, layer), 0).xyz - n0);
    steepest = max(steepest, turn);
    least = min(least, turn);
  }
  return smoothest ? (least < 2.0 ? least : 0.0) : steepest;
}

uniform int explosionMap;     // 1: vertices are placed by explosion-map look-ups, not searched
uniform int explosionRefine;  // 1: then climbed and refined by the crosshair search from the map's point
// 1: the paper's placement, Q mirrored across each map's plane and the two blended; 0: Q placed on
// the eye's ray through the blended reflection point (where it projects), which does not magnify the
// planes' normal error by 2|Q − R| (on checker-sphere: 49 px median on screen against 4 px).
uniform int explosionMirrorPlacement;
uniform sampler2DArray explosionPositions;  // per G-buffer layer L: near map on layer 2L, far map on 2L + 1
uniform sampler2DArray explosionNormals;
uniform mat4 gbufferWorldToClip;  // the eye's projection widened by the G-buffer margin

// Where a world point lands on the G-buffer, in texels (centres at +0.5); w ≤ 0 behind the eye.
vec3 gbufferCoordinateOf(vec3 world) {
  vec4 clip = gbufferWorldToClip * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec3(0.0, 0.0, -1.0);
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * vec2(textureSize(gbufferPosition, 0).xy), 1.0);
}

// MapToVirtualVertex's plane on one map: the position and normal at map coordinates `coords`,
// bilinear over the covered texels among the four nearest (the rasterizer interpolated each
// texel's triangle at its centre, so inside a triangle this is the paper's barycentric blend).
bool explosionPlane(int mapLayer, vec2 coords, out vec3 position, out vec3 normal) {
  vec2 coordinate = (coords / kExplosionExtent * 0.5 + 0.5) * vec2(textureSize(explosionPositions, 0).xy) - 0.5;
  ivec2 base = ivec2(floor(coordinate));
  vec2 f = coordinate - vec2(base);
  position = vec3(0.0);
  normal = vec3(0.0);
  float total = 0.0;
  for (int i = 0; i < 4; ++i) {
    ivec2 corner = ivec2(i & 1, i >> 1);
    float weight = (corner.x == 1 ? f.x : 1.0 - f.x) * (corner.y == 1 ? f.y : 1.0 - f.y);
    vec4 p = texelFetch(explosionPositions, ivec3(base + corner, mapLayer), 0);
    if (weight == 0.0 || p.w <= 0.0) continue;
    position += weight * p.xyz;
    normal += weight * texelFetch(explosionNormals, ivec3(base + corner, mapLayer), 0).xyz;
    total += weight;
  }
  if (total <= 0.0) return false;
  position /= total;
  normal = normalize(normal);
  return true;
}

// VirtualVertex (the paper's Figure 7). A vertex behind the part on screen is hidden: it is mirrored
// across the part's surface under it (the G-buffer is the paper's hidden map and reflector z-buffer).
// Any other is mirrored across the plane each map gives in the direction from C to it, near and far
// blended by inverse distance to their spheres. state.z counts the look-ups.
ReflectedVertex explosionMapReflection(vec3 vertex) {
  ReflectedVertex result;
  int flags = 0, lookups = 1;
  vec3 r = vec3(0.0), n = vec3(0.0, 0.0, 1.0), virtualPosition = vec3(0.0);
  vec3 onGBuffer = gbufferCoordinateOf(vertex);
  ivec2 texel = ivec2(floor(onGBuffer.xy));
  vec4 under = onGBuffer.z > 0.0 ? texelFetch(gbufferPosition, ivec3(texel, layer), 0) : vec4(0.0);
  if (under.w > 0.0 && all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, textureSize(gbufferPosition, 0).xy)) &&
      distance(eyePosition, vertex) > distance(eyePosition, under.xyz)) {
    flags |= kReflectionHidden;
    r = under.xyz;
    n = normalize(texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz);
    virtualPosition = mirrorAcrossPlane(r, n, vertex);
  } else {
    vec3 offset = vertex - explosionCentre;
    vec2 coords = explosionMapCoords(offset / max(length(offset), 1e-20));
    vec3 nearR, nearN, farR, farN;
    bool near = explosionPlane(2 * layer, coords, nearR, nearN), far = explosionPlane(2 * layer + 1, coords, farR, farN);
    lookups = 2;
    float fromCentre = length(offset);
    float nearWeight = near ? 1.0 / max(abs(fromCentre - explosionRadii.x), 1e-6) : 0.0;
    float farWeight = far ? 1.0 / max(abs(fromCentre - explosionRadii.y), 1e-6) : 0.0;
    if (nearWeight + farWeight > 0.0) {
      float total = nearWeight + farWeight;
      r = (nearWeight * (near ? nearR : vec3(0.0)) + farWeight * (far ? farR : vec3(0.0))) / total;
      n = normalize(nearWeight * (near ? nearN : vec3(0.0)) + farWeight * (far ? farN : vec3(0.0)));
      virtualPosition = explosionMirrorPlacement != 0
                            ? (nearWeight * (near ? mirrorAcrossPlane(nearR, nearN, vertex) : vec3(0.0)) +
                               farWeight * (far ? mirrorAcrossPlane(farR, farN, vertex) : vec3(0.0))) / total
                            : virtualVertex(eyePosition, r, vertex);
    } else {
      flags |= kReflectionUnsolved;
    }
  }
  vec3 atR = gbufferCoordinateOf(r);
  result.virtualPosition = vec4(virtualPosition, (flags & kReflectionUnsolved) != 0 ? 0.0 : 1.0);
  result.reflectionPoint = vec4(r, 1.0);
  result.reflectionNormal = vec4(n, 0.0);
  result.state = ivec4(atR.z > 0.0 ? ivec2(floor(atR.xy)) : ivec2(-1), lookups, flags);
  return result;
}

// The exact reflection of `vertex` in an extrusion mirror: no search, no look-up (0 steps).
ReflectedVertex solvedExtrusionReflection(vec3 vertex) {
  ReflectedVertex result;
  vec3 r, n;
  bool hidden;
  int flags = 0;
  if (!extrusionReflection(eyePosition, vertex, r, n, hidden)) {
    flags |= kReflectionUnsolved;
    result.virtualPosition = vec4(0.0);
  } else {
    // Hidden vertices go across the silhouette's tangent plane, as on the other paths below.
    if (hidden) flags |= kReflectionHidden;
    result.virtualPosition = vec4(hidden ? mirrorAcrossPlane(r, n, vertex) : virtualVertex(eyePosition, r, vertex), 1.0);
  }
  vec3 atR = gbufferCoordinateOf(r);
  result.reflectionPoint = vec4(r, 1.0);
  result.reflectionNormal = vec4(n, 0.0);
  result.state = ivec4(atR.z > 0.0 ? ivec2(floor(atR.xy)) : ivec2(-1), 0, flags);
  return result;
}

// A parametric mirror's exact surface (exactGBuffer = 1): each G-buffer texel's (u, v, patch), the
// patches' control points and the mirror's placement, for refining on the patch itself.
uniform sampler2DArray gbufferSurface;
uniform mat4 patchObjectToWorld;
#define PATCH_POINTS_BINDING 11
#include "common/bezier-patch.glsl"

const float kPatchConverged = 2e-5;      // sine between normal and bisector: a reflection point to float precision
const float kPatchStepConverged = 1e-4;  // in (u, v): Newton's next correction near a simple root
// A root this far past a patch's edge in (u, v) is still on it: float rounding. One further out lies
// on the patch's polynomial continued past the edge, not on the surface: by a crease (the teapot's
// lid seam turns its normal by 0.2°) both patches' continuations have a root just past the seam and
// the surface has none there. 1e-4 took such a root for a reflection, 179 px from any.
const float kPatchEdge = 2e-6;

// The patch's point and partial derivatives at (u, v), in world space.
void worldPatchSample(int first, vec2 uv, out vec3 position, out vec3 du, out vec3 dv) {
  bezierPatchSample(first, uv, position, du, dv);
  mat3 linear = mat3(patchObjectToWorld);
  position = (patchObjectToWorld * vec4(position, 1.0)).xyz;
  du = linear * du;
  dv = linear * dv;
}

// (H·Su, H·Sv) with H the half vector of eye and vertex: zero exactly at a reflection point.
vec2 reflectionCondition(int first, vec2 uv) {
  vec3 p, du, dv;
  worldPatchSample(first, uv, p, du, dv);
  vec3 h = normalize(eyePosition - p) + normalize(vertexWorld - p);
  return vec2(dot(h, du), dot(h, dv));
}

// The G-buffer's (u, v, patch) of the patch other than `first` nearest `edge` (a point on the edge
// of `first`) among the texel it lands on and that texel's eight neighbours: the seam may run through
// the texel, which then shows `first` itself. w ≤ 0 when none shows another patch.
vec4 surfaceAcross(vec3 edge, int first) {
  vec3 at = gbufferCoordinateOf(edge);
  vec4 across = vec4(0.0);
  if (at.z <= 0.0) return across;
  ivec2 centre = ivec2(floor(at.xy));
  float nearest = 1e30;
  for (int k = 0; k < 9; ++k) {
    ivec2 texel = centre + ivec2(k % 3 - 1, k / 3 - 1);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, textureSize(gbufferSurface, 0).xy))) continue;
    vec4 surface = texelFetch(gbufferSurface, ivec3(texel, layer), 0);
    if (surface.w <= 0.0 || 16 * int(surface.z + 0.5) == first) continue;
    float away = distance(texelFetch(gbufferPosition, ivec3(texel, layer), 0).xyz, edge);
    if (away < nearest) {
      nearest = away;
      across = surface;
    }
  }
  return across;
}

// Newton's method on the exact patch from the G-buffer's (u, v) at `texel`. 1: converged on that
// patch to a point this layer shows (in the part, not occluded), written to position and normal;
// -1: converged to a point the layer does not show (on another part, or behind the surface); 0:
// no convergence on this patch (the answer may lie on a neighbour): the G-buffer's point stands.
int refineOnPatch(ivec2 texel, out vec3 position, out vec3 normal) {
  vec4 surface = texelFetch(gbufferSurface, ivec3(texel, layer), 0);
  if (surface.w <= 0.0) return 0;
  int first = 16 * int(surface.z + 0.5);
  vec2 uv = surface.xy;
  const float e = 1e-3;  // central differences in (u, v): float keeps ~4 digits of the Jacobian
  int crossings = 0;
  for (int iteration = 0; iteration < 10; ++iteration) {
    vec3 du, dv;
    worldPatchSample(first, uv, position, du, dv);
    normal = cross(du, dv);
    if (!(dot(normal, normal) > 1e-12 * dot(du, du) * dot(dv, dv))) return 0;  // a pole
    normal = normalize(normal);
    vec2 g = reflectionCondition(first, uv);
    mat2 jacobian = mat2((reflectionCondition(first, uv + vec2(e, 0.0)) - reflectionCondition(first, uv - vec2(e, 0.0))) / (2.0 * e),
                         (reflectionCondition(first, uv + vec2(0.0, e)) - reflectionCondition(first, uv - vec2(0.0, e))) / (2.0 * e));
    if (abs(determinant(jacobian)) < 1e-20) return 0;
    vec2 step = -inverse(jacobian) * g;
    vec3 h = normalize(normalize(eyePosition - position) + normalize(vertexWorld - position));
    // A reflection point to float precision, and a simple root: by a fold of the reflection (where two
    // reflections meet and vanish, a caustic's edge) the normal can miss the bisector by less than the
    // tolerance at a point that is none, and there Newton's next step stays large. It must lie on
    // the patch: the polynomial goes on past a seam, where the surface is the neighbour's.
    bool converged = length(cross(h, normal)) < kPatchConverged && length(step) < kPatchStepConverged;
    vec2 root = uv + step;  // Newton's estimate of the root, closer than uv by the step still to go
    bool onThisPatch = all(greaterThanEqual(root, vec2(-kPatchEdge))) && all(lessThanEqual(root, vec2(1.0 + kPatchEdge)));
    if (converged && onThisPatch) {
      vec3 at = gbufferCoordinateOf(position);
      if (at.z <= 0.0) return -1;
      ivec2 shown = ivec2(floor(at.xy));
      vec4 seen = texelFetch(gbufferPosition, ivec3(shown, layer), 0);
      if (seen.w <= 0.0 || any(lessThan(shown, ivec2(0))) || any(greaterThanEqual(shown, textureSize(gbufferPosition, 0).xy)))
        return -1;
      // Occluded when the texel it lands on shows a surface nearer the eye by more than a texel's depth step.
      float depthStep = 0.0;
      for (int k = 0; k < 4; ++k) {
        vec4 neighbour = texelFetch(gbufferPosition, ivec3(shown + kNeighbours[k], layer), 0);
        if (neighbour.w > 0.0) depthStep = max(depthStep, abs(distance(eyePosition, neighbour.xyz) - distance(eyePosition, seen.xyz)));
      }
      return distance(eyePosition, seen.xyz) < distance(eyePosition, position) - 2.0 * depthStep - 1e-4 * distance(eyePosition, position) ? -1 : 1;
    }
    if (!converged) {
      if (length(step) > 0.2) step *= 0.2 / length(step);  // damped: it cannot leap across the patch
      uv += step;
      if (all(greaterThanEqual(uv, vec2(-0.01))) && all(lessThanEqual(uv, vec2(1.01)))) continue;
    }
    // Off the patch, or converged just past its edge: carry on from the neighbour the G-buffer shows
    // at the edge it left by (the G-buffer doubles as the patches' adjacency), twice at most.
    vec3 edge, unusedU, unusedV;
    worldPatchSample(first, clamp(uv, 0.0, 1.0), edge, unusedU, unusedV);
    if (++crossings > 2) return 0;
    vec4 next = surfaceAcross(edge, first);
    if (next.w <= 0.0) return 0;
    first = 16 * int(next.z + 0.5);
    uv = next.xy;
  }
  return 0;
}

// Finds the reflection of `vertex` (world space) in the mirror on G-buffer layer `layer`;
// state.xy is the texel reached (the next search's seed), state.z the steps, state.w the flags.
// `retryWhenLost`: if the refinement from a seeded climb is lost, search again from the pyramid
// (seeds from last frame; this frame's seeds, as edge midpoints get, are never that stale).
ReflectedVertex searchReflection(vec3 vertex, ivec2 seed, bool useSeed, bool retryWhenLost) {
  vertexWorld = vertex;
  if (extrusion != 0) return solvedExtrusionReflection(vertex);
  int steps = 0, flags = 0;
  if (explosionMap != 0) {
    ReflectedVertex mapped = explosionMapReflection(vertex);
    if (explosionRefine == 0) return mapped;
    steps = mapped.state.z;  // the look-ups, then the climb's windows
    // Where the maps have no answer (a vertex inside the near sphere, as an object resting on the
    // mirror's foot is), the refinement starts cold from the pyramid, as the crosshair search would.
    seed = mapped.state.xy;
    useSeed = (mapped.state.w & kReflectionUnsolved) == 0;
  }
  float value = kInvalid;
  ivec2 texel = seed;
  bool hiddenExactly = analytic != 0 && behindQuadric(eyePosition, vertexWorld);  // region C, decided once
  bool warm = rayHierarchy == 0 && useSeed && objectiveAt(texel, 0) > kInvalid;
  if (warm) texel = climb(texel, 0, maxWalkSteps, steps, value);
  if (rayHierarchy != 0) texel = rayHierarchySearch(hiddenExactly, steps, flags, value);
  bool fromPyramid = rayHierarchy == 0 && (!warm || steps >= maxWalkSteps);  // no seed, or the seed was too far
  vec3 r, n;
  // At most two rounds, written as a loop so the pyramid search and the refinement are each
  // compiled once (this function is inlined into every search).
  while (true) {
    if (fromPyramid && (flags & kReflectionColdStart) == 0) {
      int coldSteps = 0;
      float coldValue;
      ivec2 coldTexel = coldSearch(coldSteps, coldValue);
      steps += coldSteps;
      flags |= kReflectionColdStart;
      if (coldValue > value) {
        texel = coldTexel;
        value = coldValue;
      }
    }
    if (value <= kInvalid || analytic == 0) break;
    bool converged = refineOnQuadric(texelFetch(gbufferPosition, ivec3(texel, layer), 0).xyz, r, n);
    // A stale seed (the camera jumped) can stall the climb far from the answer, where the refinement
    // cannot reach it: search again from the pyramid. Hidden vertices have no answer to converge to;
    // the ray hierarchy has no seed to be stale.
    if (converged || !retryWhenLost || rayHierarchy != 0 || (flags & kReflectionColdStart) != 0 || hiddenExactly) break;
    fromPyramid = true;
    value = kInvalid;  // the stalled texel must not win against the pyramid's
  }

  ReflectedVertex result;
  bool refinedExactly = value > kInvalid && analytic != 0;  // r and n came from refineOnQuadric
  bool blocked = false;
  vec2 refined = vec2(texel);
  if (!refinedExactly && value > kInvalid) refined = refine(texel, blocked);
  if (!refinedExactly && (value <= kInvalid || !surfaceAt(refined, r, n))) {
    vec4 p = texelFetch(gbufferPosition, ivec3(texel, layer), 0);
    r = p.xyz;
    n = normalize(texelFetch(gbufferNormal, ivec3(texel, layer), 0).xyz);
    if (value <= kInvalid) flags |= kReflectionUnsolved;
  }
  if ((flags & kReflectionUnsolved) != 0) {
    result.virtualPosition = vec4(0.0);
  } else {
    // Behind the mirror: region C (Estalella et al. 2006, §5.1), exactly for an analytic mirror.
    // On a mesh, a vertex is hidden behind the tangent plane at the best point, or when that point
    // is held on the mirror's (part's) outline with normal and bisector still apart: the tangent
    // plane alone (the paper's test) holds only on convex mirrors, and a concave part's best point
    // on its rim can have the vertex in front.
    // A hidden vertex is mirrored across the silhouette's tangent plane (not the paper's eq. 1,
    // which lands inside the silhouette and smears), which projects it just outside; for an
    // analytic mirror that silhouette point is exact, so it moves smoothly. A visible vertex goes
    // on the eye's ray through R instead: the same point when R is exact, but it needs no normal,
    // which mirroring would magnify by about 2|V − R| at grazing reflection points.
    // On the exact patch: Newton's answer decides where it converges; the residual rule elsewhere.
    int onPatch = 0;
    if (exactGBuffer != 0) {
      vec3 exactR, exactN;
      onPatch = refineOnPatch(ivec2(round(refined)), exactR, exactN);
      if (onPatch > 0) {
        r = exactR;
        n = exactN;
      }
    }
    float residual = length(tangentialBisector(r, n));
    bool noReflection = exactGBuffer != 0 ? onPatch <= 0
                                          : blocked && residual > max(kNoReflectionResidual, normalTurnPerTexel(texel, false));
    bool hidden = analytic != 0 ? hiddenExactly : dot(vertexWorld - r, n) < 0.0 || noReflection;
    if (hidden) {
      flags |= kReflectionHidden;
      vec3 silhouette, silhouetteNormal;
      if (analytic != 0 && silhouettePointToward(eyePosition, vertexWorld, silhouette, silhouetteNormal)) {
        r = silhouette;
        n = silhouetteNormal;
      }
    }
    result.virtualPosition = vec4(hidden ? mirrorAcrossPlane(r, n, vertexWorld) : virtualVertex(eyePosition, r, vertexWorld), 1.0);
  }
  result.reflectionPoint = vec4(r, 1.0);
  result.reflectionNormal = vec4(n, 0.0);
  result.state = ivec4(texel, steps, flags);
  return result;
}
