#version 430 core
// Mirror surface samples for the search. A mirror with an analytic shape (sphere, ellipsoid) is
// ray-cast exactly per fragment: its mesh only bounds it, so facets and interpolated normals add
// no error to the reflection points.

in vec3 worldPosition;
in vec3 worldNormal;

uniform int analytic;             // 1: intersect the quadric below instead of using the mesh
uniform vec3 eyePosition;
uniform mat4 worldToObject;
uniform mat3 objectNormalToWorld;
uniform vec3 quadricCenter;       // object space
uniform vec3 quadricRadii;
uniform mat4 worldToClip;

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  if (analytic == 0) {
    outPosition = vec4(worldPosition, 1.0);
    outNormal = vec4(normalize(worldNormal), 0.0);
    return;
  }
  // Eye ray through this fragment, in the quadric's unit-sphere space; solved in a numerically
  // stable form (half-b, with the root nearer the eye taken from the product of roots).
  vec3 origin = ((worldToObject * vec4(eyePosition, 1.0)).xyz - quadricCenter) / quadricRadii;
  vec3 through = ((worldToObject * vec4(worldPosition, 1.0)).xyz - quadricCenter) / quadricRadii;
  vec3 direction = normalize(through - origin);
  float halfB = dot(origin, direction);
  float c = dot(origin, origin) - 1.0;
  float discriminant = halfB * halfB - c;
  if (discriminant < 0.0) discard;
  float q = -halfB - sign(halfB) * sqrt(discriminant);
  float t0 = q, t1 = c / q;
  float t = min(t0, t1) > 0.0 ? min(t0, t1) : max(t0, t1);
  if (t <= 0.0) discard;
  vec3 unitPoint = origin + t * direction;
  vec3 objectPoint = quadricCenter + unitPoint * quadricRadii;
  vec3 world = (inverse(worldToObject) * vec4(objectPoint, 1.0)).xyz;
  outPosition = vec4(world, 1.0);
  outNormal = vec4(normalize(objectNormalToWorld * (unitPoint / quadricRadii)), 0.0);
  vec4 clip = worldToClip * vec4(world, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}
