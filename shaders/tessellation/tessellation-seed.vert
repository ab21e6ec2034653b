#version 440 core
// Tessellation input: the triangles of one reflected object with their corners' search results,
// captured by transform feedback as TessellatedVertex records (three per triangle).

#include "common/reflected-vertex-buffer.glsl"
#include "common/tessellated-vertex.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform uint firstSlot;

layout(xfb_buffer = 0, xfb_offset = 0) out TessellatedRecord {
  vec4 positionU;
  vec4 normalV;
  vec4 virtualFlags;
  vec4 reflectionTexelX;
  vec4 normalTexelY;
} outRecord;

void main() {
  TessellatedVertex v = makeTessellatedVertex((objectToWorld * vec4(inPosition, 1.0)).xyz, normalToWorld * inNormal, inUv,
                                              reflected[firstSlot + uint(gl_VertexID)]);
  outRecord.positionU = v.positionU;
  outRecord.normalV = v.normalV;
  outRecord.virtualFlags = v.virtualFlags;
  outRecord.reflectionTexelX = v.reflectionTexelX;
  outRecord.normalTexelY = v.normalTexelY;
}
