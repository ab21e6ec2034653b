#version 430 core
// Mirror surface samples for the search from a mesh mirror's triangles. A mirror of several parts is
// drawn whole for depth, but only the texels of the layer's own part are marked. No gl_FragDepth
// write, so the rasterizer may test depth before shading and skip hidden (back) faces.

in vec3 worldPosition;
in vec3 worldNormal;

uniform int part;  // the part this layer holds; -1 when the mirror is one part

layout(std430, binding = 0) readonly buffer TriangleParts {
  uint packedParts[];  // the part of each triangle of the mesh, four bytes to a uint
};

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  bool inPart = part < 0 || int((packedParts[gl_PrimitiveID >> 2] >> (8 * (gl_PrimitiveID & 3))) & 0xFFu) == part;
  outPosition = vec4(worldPosition, inPart ? 1.0 : 0.0);
  outNormal = vec4(normalize(worldNormal), 0.0);
}
