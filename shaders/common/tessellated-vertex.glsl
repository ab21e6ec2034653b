// One vertex of a tessellated virtual triangle, as the emission kernel writes it and storage buffers
// read it: five vec4, 80 bytes, three per triangle. The GL twin is passes/TessellationBuffers.
#include "common/reflected-vertex.glsl"

struct TessellatedVertex {
  vec4 positionU;        // world position of the reflected surface point, uv.x
  vec4 normalV;          // its world normal, uv.y
  vec4 virtualFlags;     // virtual position (world), reflection flags as a float
  vec4 reflectionTexelX; // reflection point R, seed texel x as a float
  vec4 normalTexelY;     // unit mirror normal at R, seed texel y as a float
};

TessellatedVertex makeTessellatedVertex(vec3 position, vec3 normal, vec2 uv, ReflectedVertex reflection) {
  return TessellatedVertex(vec4(position, uv.x), vec4(normal, uv.y),
                           vec4(reflection.virtualPosition.xyz, float(reflection.state.w)),
                           vec4(reflection.reflectionPoint.xyz, float(reflection.state.x)),
                           vec4(reflection.reflectionNormal.xyz, float(reflection.state.y)));
}
