#version 430 core
// Mirror surface samples for the search. A mirror with an analytic shape (sphere, ellipsoid) is
// ray-cast exactly per fragment inside its proxy box, so facets and interpolated normals add no
// error to the reflection points. A mesh mirror of several parts is drawn whole for depth, but only
// the texels of the layer's own part are marked.
#include "common/quadric.glsl"

in vec3 worldPosition;
in vec3 worldNormal;

uniform vec3 eyePosition;
uniform mat4 worldToClip;
uniform int part;  // the part this layer holds; -1 when the mirror is one part

layout(std430, binding = 0) readonly buffer TriangleParts {
  uint packedParts[];  // the part of each triangle of the mesh, four bytes to a uint
};

layout(location = 0) out vec4 outPosition;  // w = 1 marks a mirror texel
layout(location = 1) out vec4 outNormal;

void main() {
  if (analytic == 0) {
    bool inPart = part < 0 || int((packedParts[gl_PrimitiveID >> 2] >> (8 * (gl_PrimitiveID & 3))) & 0xFFu) == part;
    outPosition = vec4(worldPosition, inPart ? 1.0 : 0.0);
    outNormal = vec4(normalize(worldNormal), 0.0);
    // gl_FragDepth is written below, so every path must write it: left unset it is undefined
    // (llvmpipe: the first fragment wins), and back faces overwrote the front of mesh mirrors.
    gl_FragDepth = gl_FragCoord.z;
    return;
  }
  vec3 world, normal;
  if (!eyeRayHitsQuadric(eyePosition, worldPosition - eyePosition, world, normal)) discard;
  outPosition = vec4(world, 1.0);
  outNormal = vec4(normal, 0.0);
  gl_FragDepth = clipDepth(worldToClip, world);
}
