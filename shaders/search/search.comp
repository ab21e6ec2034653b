#version 430 core
// Reflection-point search (search/reflection-search.glsl) for the vertices of one object in one mirror,
// each seeded with its texel from last frame (coherence).
layout(local_size_x = 64) in;

#include "search/reflection-search.glsl"
#include "common/reflected-vertex-buffer.glsl"
#include "common/search-statistics.glsl"

layout(std430, binding = 0) readonly buffer MeshVertices {
  float meshVertex[];  // scene::Vertex: position xyz, normal xyz, uv — 8 floats
};

uniform mat4 objectToWorld;
uniform uint firstSlot;
uniform uint vertexCount;
uniform int useCoherence;  // 0 forces cold starts (first frame, camera jump, benchmarks)

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= vertexCount) return;
  uint slot = firstSlot + index;
  vec3 vertex = (objectToWorld * vec4(meshVertex[8u * index], meshVertex[8u * index + 1u], meshVertex[8u * index + 2u], 1.0)).xyz;
  ReflectedVertex last = reflected[slot];
  ReflectedVertex result = searchReflection(vertex, last.state.xy, useCoherence != 0 && (last.state.w & kReflectionUnsolved) == 0, true);
  reflected[slot] = result;
  countSearch(result.state.z, result.state.w);
}
