// Refinement below the texel: Gauss–Newton on the bilinear surface through the G-buffer's texel centres.
#include "search/core.glsl"

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
