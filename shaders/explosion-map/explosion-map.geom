#version 430 core
// Fills a part's front-facing and profile triangles into the map (profile ones with their back-facing
// normals fixed), and for a profile triangle with two back-facing vertices the paper's extension
// polygon: their edge pushed out past the map circle, so the unreflected directions are covered too.
#include "common/explosion-map.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 7) out;

in vec3 mapWorldPosition[];
in vec3 mapWorldNormal[];
in vec2 mapCoords[];
in float frontFacing[];

uniform int part;  // the part this map is for; -1 when the mirror is one part
layout(std430, binding = 0) readonly buffer TriangleParts {
  uint packedParts[];  // the part of each triangle of the mesh, four bytes to a uint
};

out vec3 worldPosition;
out vec3 worldNormal;
flat out float kind;  // 1: a mirror triangle, 2: an extension polygon

void emitAt(vec2 coords, int corner, float depth, float polygonKind) {
  worldPosition = mapWorldPosition[corner];
  worldNormal = mapWorldNormal[corner];
  kind = polygonKind;
  gl_Position = vec4(coords / kExplosionExtent, depth, 1.0);
  EmitVertex();
}

void main() {
  if (part >= 0 && int((packedParts[gl_PrimitiveIDIn >> 2] >> (8 * (gl_PrimitiveIDIn & 3))) & 0xFFu) != part) return;
  float front = frontFacing[0] + frontFacing[1] + frontFacing[2];
  if (front == 0.0) return;  // wholly back-facing: no reflected direction of its own
  // Where triangles overlap on the map, the more frontal wins; extension polygons lose to all.
  float depth = 0.5 - 0.1 * front;
  for (int i = 0; i < 3; ++i) emitAt(mapCoords[i], i, depth, 1.0);
  EndPrimitive();
  if (front != 1.0) return;
  int front0 = frontFacing[0] == 1.0 ? 0 : (frontFacing[1] == 1.0 ? 1 : 2);
  int a = (front0 + 1) % 3, b = (front0 + 2) % 3;  // the two back-facing corners
  vec2 ta = mapCoords[a], tb = mapCoords[b];
  vec2 outA = ta * (kExtensionRadius / max(length(ta), 1e-6)), outB = tb * (kExtensionRadius / max(length(tb), 1e-6));
  emitAt(ta, a, 0.9, 2.0);
  emitAt(tb, b, 0.9, 2.0);
  emitAt(outA, a, 0.9, 2.0);
  emitAt(outB, b, 0.9, 2.0);
  EndPrimitive();
}
