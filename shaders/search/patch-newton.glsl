// Newton's method on a parametric mirror's exact Bézier patches, from the texel the search found.
#include "search/core.glsl"

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
