// What a virtual-objects vertex shader hands the geometry shader, from either source: scene
// vertices with their search slots, or the vertices adaptive tessellation produced.

uniform mat4 worldToClip;  // far plane pushed out: virtual vertices lie up to a path length away

out VertexData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionNormal;
  flat int flags;
} outVertex;

invariant gl_Position;  // the depth pre-pass and the shading pass must produce equal depths

void emitVirtualVertex(vec3 worldPosition, vec3 worldNormal, vec2 uv, vec3 virtualPosition, vec3 reflectionNormal,
                       int flags) {
  outVertex.worldPosition = worldPosition;
  outVertex.worldNormal = worldNormal;
  outVertex.surfaceUv = uv;
  outVertex.reflectionNormal = reflectionNormal;
  outVertex.flags = flags;
  gl_Position = worldToClip * vec4(virtualPosition, 1.0);
  // A hidden vertex sits on the silhouette, where true reflections of nearer surfaces also land:
  // keep where it projects but not its depth, so its triangles never hide a true reflection.
  if ((flags & kReflectionHidden) != 0) gl_Position.z = gl_Position.w;
}
