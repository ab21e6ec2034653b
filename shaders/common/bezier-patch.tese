#version 430 core
// Evaluates the Bézier patch at each vertex the tessellator made: exact position and normal, the
// (u, v) on the patch and the patch's index, for the scene and the mirror G-buffer alike.

layout(quads, equal_spacing, ccw) in;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform mat4 worldToClip;

#include "common/bezier-patch.glsl"

out vec3 worldPosition;
out vec3 worldNormal;
out vec2 surfaceUv;
flat out int patchIndex;

void main() {
  int first = 16 * gl_PrimitiveID;
  vec2 uv = gl_TessCoord.xy;
  vec3 position, du, dv;
  bezierPatchSample(first, uv, position, du, dv);
  vec3 normal = cross(du, dv);
  if (!(dot(normal, normal) > 1e-12 * dot(du, du) * dot(dv, dv))) {
    // A pole (a collapsed edge) has no normal of its own: take its limit, a hair inside the patch.
    vec3 inside, insideU, insideV;
    bezierPatchSample(first, mix(vec2(0.5), uv, 0.999), inside, insideU, insideV);
    normal = cross(insideU, insideV);
  }
  vec4 world = objectToWorld * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = normalToWorld * normal;
  surfaceUv = uv;
  patchIndex = gl_PrimitiveID;
  gl_Position = worldToClip * world;
}
