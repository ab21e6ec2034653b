// No search: Ofek & Rappoport's (1998) explosion-map look-ups (common/explosion-map.glsl), optionally
// refined by the crosshair search from the point they give.
#include "common/explosion-map.glsl"
#include "search/core.glsl"

uniform int explosionMap;     // 1: vertices are placed by explosion-map look-ups, not searched
uniform int explosionRefine;  // 1: then climbed and refined by the crosshair search from the map's point
// 1: the paper's placement, Q mirrored across each map's plane and the two blended; 0: Q placed on
// the eye's ray through the blended reflection point (where it projects), which does not magnify the
// planes' normal error by 2|Q − R| (on checker-sphere: 49 px median on screen against 4 px).
uniform int explosionMirrorPlacement;
uniform sampler2DArray explosionPositions;  // per G-buffer layer L: near map on layer 2L, far map on 2L + 1
uniform sampler2DArray explosionNormals;

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
