// No search: on a mirror declared as a linear extrusion, Ofek & Rappoport's exact 2-D reduction.
#include "common/extrusion.glsl"
#include "search/core.glsl"

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
    // Hidden vertices go across the silhouette's tangent plane, as searchReflection places them.
    if (hidden) flags |= kReflectionHidden;
    result.virtualPosition = vec4(hidden ? mirrorAcrossPlane(r, n, vertex) : virtualVertex(eyePosition, r, vertex), 1.0);
  }
  vec3 atR = gbufferCoordinateOf(r);
  result.reflectionPoint = vec4(r, 1.0);
  result.reflectionNormal = vec4(n, 0.0);
  result.state = ivec4(atR.z > 0.0 ? ivec2(floor(atR.xy)) : ivec2(-1), 0, flags);
  return result;
}
