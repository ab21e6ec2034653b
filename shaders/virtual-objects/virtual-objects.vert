#version 430 core
// Virtual objects from a reflected object's own mesh: each vertex with its search result, for the
// geometry shader to place its triangle.
#include "common/reflected-vertex-buffer.glsl"
#include "common/tessellated-vertex.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform uint firstSlot;

out CornerData {
  TessellatedVertex corner;
} outCorner;

void main() {
  outCorner.corner = makeTessellatedVertex((objectToWorld * vec4(inPosition, 1.0)).xyz, normalToWorld * inNormal, inUv,
                                           reflected[firstSlot + uint(gl_VertexID)]);
}
