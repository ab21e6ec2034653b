#version 430 core
// Keeps a virtual triangle only where it can be a true reflection, so none smears across the mirror:
// every corner has a reflection point, at least one is not hidden (region C), and the corners'
// mirror normals are less than 90° apart: corners on far sides of a mirror, or on the inside and
// outside of a bowl, belong to different reflections that one flat triangle cannot join.
// On a concave or saddle part every corner must have its reflection point there: a corner without
// one has no place on the part from which the triangle could be completed (on a convex part it is
// mirrored just beyond the silhouette, where the triangle is cut off).
#include "common/reflected-vertex.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;
  vec3 reflectionNormal;
  flat int flags;
} inVertex[];

uniform int everyCornerReflected;  // 1 on concave and saddle parts

out FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;
} outFragment;

void main() {
  int allFlags = inVertex[0].flags | inVertex[1].flags | inVertex[2].flags;
  int commonFlags = inVertex[0].flags & inVertex[1].flags & inVertex[2].flags;
  if ((allFlags & kReflectionUnsolved) != 0 || (commonFlags & kReflectionHidden) != 0) return;
  if (everyCornerReflected != 0 && (allFlags & kReflectionHidden) != 0) return;
  for (int i = 0; i < 3; ++i)
    if (dot(inVertex[i].reflectionNormal, inVertex[(i + 1) % 3].reflectionNormal) < 0.0) return;
  for (int i = 0; i < 3; ++i) {
    outFragment.worldPosition = inVertex[i].worldPosition;
    outFragment.worldNormal = inVertex[i].worldNormal;
    outFragment.surfaceUv = inVertex[i].surfaceUv;
    outFragment.reflectionPoint = inVertex[i].reflectionPoint;
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
