// The reflection-point search for one vertex (searchReflection) over the strategies in search/: the
// mirror texel by the crosshair climb (crosshair.glsl) or Szabo's ray hierarchy (ray-hierarchy-search.glsl),
// then refinement below it (refine.glsl, refine-quadric.glsl, patch-newton.glsl); or no search, by
// explosion-map look-ups (explosion-map-search.glsl) or an extrusion's exact solution
// (extrusion-reflection.glsl). Shared by the search of scene vertices (search/search.comp) and of the
// vertices adaptive tessellation adds (tessellation/).
#include "search/crosshair.glsl"
#include "search/explosion-map-search.glsl"
#include "search/extrusion-reflection.glsl"
#include "search/patch-newton.glsl"
#include "search/ray-hierarchy-search.glsl"
#include "search/refine-quadric.glsl"
#include "search/refine.glsl"

// On a mesh the best point of a part whose reflection lies beyond its outline (hidden behind a
// convex part's silhouette, or on another part) stops on the outline with normal and bisector this
// far apart (sine), or as far as the normal turns from one texel to the next on a mirror a few texels
// wide: such a vertex has no reflection point in the part.
const float kNoReflectionResidual = 0.05;
// 1: the G-buffer holds the exact surface (a parametric mirror's patches): Newton's method on the
// patch (search/patch-newton.glsl), not the residual, decides whether a vertex has a reflection point.
uniform int exactGBuffer;

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
