// The exact surface of an analytic mirror (sphere, ellipsoid): where the eye's ray first meets it.
// The G-buffer pass samples it per fragment; the search refines reflection points on it, so neither
// depends on the mirror's mesh facets. Uniforms set by server/passes/QuadricUniforms.
#include "common/clip-depth.glsl"

uniform int analytic;             // 1: the mirror has the quadric below and it is closed
uniform mat4 quadricWorldToObject;
uniform mat4 quadricObjectToWorld;
uniform mat3 quadricNormalToWorld;
uniform vec3 quadricCenter;       // object space
uniform vec3 quadricRadii;

vec3 toUnitSpace(vec3 world) { return ((quadricWorldToObject * vec4(world, 1.0)).xyz - quadricCenter) / quadricRadii; }

// World position and unit normal of the quadric at a point of its unit sphere.
void quadricSurface(vec3 unitPoint, out vec3 position, out vec3 normal) {
  position = (quadricObjectToWorld * vec4(quadricCenter + unitPoint * quadricRadii, 1.0)).xyz;
  normal = normalize(quadricNormalToWorld * (unitPoint / quadricRadii));
}

// The uvSphere parametrisation of a world point on the quadric (reference/AnalyticSurface::uv):
// (longitude, latitude) / (2π, π), longitude turning from +x towards −z.
vec2 quadricUv(vec3 world) {
  vec3 p = normalize(toUnitSpace(world));
  float longitude = atan(-p.z, p.x);
  if (longitude < 0.0) longitude += 6.28318530718;
  return vec2(longitude / 6.28318530718, acos(clamp(-p.y, -1.0, 1.0)) / 3.14159265359);
}

// Whether the eye sees this point of the unit sphere (it lies on the eye's side of its tangent plane).
bool facesEye(vec3 unitPoint, vec3 unitEye) { return dot(unitPoint, unitEye) >= 1.0; }

// First hit of the ray from `eye` along `direction` (world space); false when it misses.
// Solved in the quadric's unit-sphere space in a stable form (half-b, the second root from the
// product of roots), which stays exact at grazing incidence; the discriminant comes from the ray's
// closest approach, not halfB² − c, which cancels to nothing for an eye 10^4 radii away.
bool eyeRayHitsQuadric(vec3 eye, vec3 worldDirection, out vec3 position, out vec3 normal) {
  vec3 origin = toUnitSpace(eye);
  vec3 direction = normalize(mat3(quadricWorldToObject) * worldDirection / quadricRadii);
  float halfB = dot(origin, direction);
  float c = dot(origin, origin) - 1.0;
  vec3 closest = origin - halfB * direction;
  float discriminant = 1.0 - dot(closest, closest);
  if (discriminant < 0.0) return false;
  float q = -halfB - (halfB < 0.0 ? -1.0 : 1.0) * sqrt(discriminant);
  float t0 = q, t1 = c / q;
  float t = min(t0, t1) > 0.0 ? min(t0, t1) : max(t0, t1);
  if (!(t > 0.0)) return false;
  quadricSurface(origin + t * direction, position, normal);
  return true;
}

// Region C of an analytic mirror, exactly: the vertex has no reflection point the eye can see when
// it lies in the shadow the eye's tangent cone casts behind the quadric. Tested in unit-sphere space
// (affine maps keep tangency and sides of planes): inside the cone, beyond the silhouette's plane.
bool behindQuadric(vec3 eye, vec3 vertex) {
  vec3 origin = toUnitSpace(eye), target = toUnitSpace(vertex);
  float distance = length(origin);
  if (distance <= 1.0) return false;
  vec3 axis = origin / distance;
  float along = dot(target, axis);
  if (along >= 1.0 / distance) return false;  // on the eye's side of the silhouette
  // Inside the cone: the angle from the axis, seen from the eye, is below the cone's half-angle,
  // whose sine is 1 / distance. Compared as sines: a far eye's cosine rounds to 1.
  vec3 fromEye = target - origin;
  vec3 across = cross(fromEye, axis);
  return dot(fromEye, -axis) > 0.0 && dot(across, across) * distance * distance < dot(fromEye, fromEye);
}

// The point of the quadric's silhouette (seen from `eye`) in the plane of the eye, the centre and
// `vertex`, on the vertex's side: where a vertex hidden behind the mirror is reflected from. It is
// where the vertex's reflection point arrives as the vertex becomes hidden, and it moves smoothly
// with eye and vertex, unlike the silhouette texel the search stops at, whose normal turns fast
// enough to throw the mirrored vertex tens of pixels between frames. False when the eye is inside
// or the three points are collinear.
bool silhouettePointToward(vec3 eye, vec3 vertex, out vec3 position, out vec3 normal) {
  vec3 origin = toUnitSpace(eye), target = toUnitSpace(vertex);
  float distanceSquared = dot(origin, origin);
  if (distanceSquared <= 1.0) return false;
  vec3 axis = origin * inversesqrt(distanceSquared);
  vec3 across = target - dot(target, axis) * axis;
  if (dot(across, across) < 1e-12 * max(dot(target, target), 1.0)) return false;
  // In unit-sphere space the silhouette is the circle p·origin = 1 on the unit sphere.
  quadricSurface(axis * inversesqrt(distanceSquared) + normalize(across) * sqrt(1.0 - 1.0 / distanceSquared),
                 position, normal);
  return true;
}
