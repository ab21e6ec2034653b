#version 430 core
// Virtual objects: each vertex placed at its virtual position from the search, but carrying its
// original world position and normal, so it is lit where the real object is.

#include "common/reflected-vertex-buffer.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 objectToWorld;
uniform mat3 normalToWorld;
uniform mat4 worldToClip;  // far plane pushed out: virtual vertices lie up to a path length away
uniform uint firstSlot;

out VertexData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;  // where the eye sees this vertex: the viewer for its shading
  vec3 reflectionNormal;
  flat int flags;
} outVertex;

invariant gl_Position;  // the depth pre-pass and the shading pass must produce equal depths

void main() {
  ReflectedVertex r = reflected[firstSlot + uint(gl_VertexID)];
  outVertex.worldPosition = (objectToWorld * vec4(inPosition, 1.0)).xyz;
  outVertex.worldNormal = normalToWorld * inNormal;
  outVertex.surfaceUv = inUv;
  outVertex.reflectionPoint = r.reflectionPoint.xyz;
  outVertex.reflectionNormal = r.reflectionNormal.xyz;
  outVertex.flags = r.state.w;
  gl_Position = worldToClip * vec4(r.virtualPosition.xyz, 1.0);
  // A hidden vertex sits on the silhouette, where true reflections of nearer surfaces also land:
  // keep where it projects but not its depth, so its triangles never hide a true reflection.
  if ((r.state.w & kReflectionHidden) != 0) gl_Position.z = gl_Position.w;
}
