#version 430 core
// Mirror surface samples for the search from a parametric mirror, drawn through the patch
// tessellation (common/bezier-patch.tesc, .tese): every texel takes position and normal from its exact
// Bézier patch where the eye's ray through the texel meets it (Newton's method on (u, v, t) from the
// interpolated (u, v)), so the tessellation's facets add no error. Parts as in
// mirror-gbuffer-mesh.frag, each texel taking the part of the grid triangle (scene::parametricMesh)
// its (u, v) falls in: the grid is what the parts were split on. A mirror of several parts is drawn
// once, whole, into scratch textures, every texel recording its part, and each part's layer is copied
// from them (part-layer.frag).

in vec3 worldPosition;
in vec3 worldNormal;
in vec2 surfaceUv;
flat in int patchIndex;

uniform int severalParts;  // 1 when the mirror has several parts: the texel's part is recorded
uniform int patchSegments;  // grid quads per patch side of the parametric mesh
uniform mat4 objectToWorld;
uniform mat4 worldToObject;
uniform mat3 normalToWorld;
uniform vec3 eyePosition;  // world

layout(std430, binding = 0) readonly buffer TriangleParts {
  uint packedParts[];  // the part of each triangle of the mesh, four bytes to a uint
};

#include "common/bezier-patch.glsl"

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;   // w = the texel's part + 1
layout(location = 2) out vec4 outSurface;  // (u, v, patch, 1)

// The grid triangle of the parametric mesh at (u, v) on patch `patchIndex`: quad (i, j) holds
// triangles (a, b, d) below its diagonal and (a, d, c) above it (math::patchGridTriangle).
int gridTriangle(vec2 uv) {
  vec2 cell = uv * float(patchSegments);
  ivec2 quad = clamp(ivec2(floor(cell)), ivec2(0), ivec2(patchSegments - 1));
  vec2 inQuad = cell - vec2(quad);
  return 2 * (patchIndex * patchSegments * patchSegments + quad.y * patchSegments + quad.x) + (inQuad.x < inQuad.y ? 1 : 0);
}

void main() {
  int first = 16 * patchIndex;
  // The texel's eye ray in object space passes through the tessellation's point; the patch lies
  // within a fraction of a texel of it, so a few Newton steps from its (u, v) reach the exact surface.
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
  // At a pole (a collapsed edge) the patch has no normal of its own; the tessellation's is its limit.
  vec3 worldN = dot(normal, normal) > 1e-8 * dot(du, du) * dot(dv, dv) ? normalToWorld * normal : worldNormal;
  int triangle = gridTriangle(uv);
  int texelPart = severalParts == 0 ? 0 : int((packedParts[triangle >> 2] >> (8 * (triangle & 3))) & 0xFFu);
  outPosition = vec4((objectToWorld * vec4(position, 1.0)).xyz, 1.0);
  outNormal = vec4(normalize(worldN), float(texelPart + 1));
  outSurface = vec4(uv, float(patchIndex), 1.0);
}
