#version 430 core
// Mirror surface samples for the search from a parametric mirror: its grid is drawn for coverage
// and depth, and every texel takes position and normal from its exact Bézier patch where the eye's
// ray through the texel meets it (Newton's method on (u, v, t) from the interpolated (u, v)), so the
// grid's facets and interpolated normals add no error. Parts as in mirror-gbuffer-mesh.frag.

in vec3 worldPosition;
in vec3 worldNormal;
in vec2 surfaceUv;

uniform int part;  // the part this layer holds; -1 when the mirror is one part
uniform int trianglesPerPatch;  // of the grid (scene::parametricMesh): triangle t lies on patch t / this
uniform mat4 objectToWorld;
uniform mat4 worldToObject;
uniform mat3 normalToWorld;
uniform vec3 eyePosition;  // world

layout(std430, binding = 0) readonly buffer TriangleParts {
  uint packedParts[];  // the part of each triangle of the mesh, four bytes to a uint
};
layout(std430, binding = 1) readonly buffer PatchPoints {
  vec4 patchPoints[];  // 16 per patch, object space
};

#include "common/bezier-patch.glsl"

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  bool inPart = part < 0 || int((packedParts[gl_PrimitiveID >> 2] >> (8 * (gl_PrimitiveID & 3))) & 0xFFu) == part;
  int first = 16 * (gl_PrimitiveID / trianglesPerPatch);
  // The texel's eye ray in object space passes through the grid's point; the patch lies within a
  // fraction of a texel of it, so a few Newton steps from its (u, v) reach the exact surface.
  vec3 eye = (worldToObject * vec4(eyePosition, 1.0)).xyz;
  vec3 direction = (worldToObject * vec4(worldPosition, 1.0)).xyz - eye;
  vec2 uv = clamp(surfaceUv, 0.0, 1.0);
  float t = 1.0;
  vec3 position, du, dv;
  for (int i = 0; i < 3; ++i) {
    bezierPatchSample(first, uv, position, du, dv);
    mat3 jacobian = mat3(du, dv, -direction);
    if (abs(determinant(jacobian)) < 1e-20) break;
    vec3 step = inverse(jacobian) * (eye + t * direction - position);
    uv = clamp(uv + step.xy, 0.0, 1.0);  // past the edge is the neighbour's: its edge is shared
    t += step.z;
  }
  bezierPatchSample(first, uv, position, du, dv);
  vec3 normal = cross(du, dv);
  // At a pole (a collapsed edge) the patch has no normal of its own; the grid's is its limit.
  vec3 worldN = dot(normal, normal) > 1e-8 * dot(du, du) * dot(dv, dv) ? normalToWorld * normal : worldNormal;
  outPosition = vec4((objectToWorld * vec4(position, 1.0)).xyz, inPart ? 1.0 : 0.0);
  outNormal = vec4(normalize(worldN), 0.0);
}
