#version 430 core
// Virtual objects: each vertex placed at its virtual position from the search, but carrying its
// original world position and normal, so it is lit where the real object is.

#include "common/reflected-vertex-buffer.glsl"
#include "common/virtual-vertex-output.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform uint firstSlot;

void main() {
  ReflectedVertex r = reflected[firstSlot + uint(gl_VertexID)];
  emitVirtualVertex((objectToWorld * vec4(inPosition, 1.0)).xyz, normalToWorld * inNormal, inUv, r.virtualPosition.xyz,
                    r.reflectionNormal.xyz, r.state.w);
}
