// The reflected-vertex slots as a storage buffer, for the stages that read or write them
// (geometry shaders include only reflected-vertex.glsl: some drivers allow them no storage blocks).
#include "common/reflected-vertex.glsl"

layout(std430, binding = 1) buffer ReflectedVertices {
  ReflectedVertex reflected[];
};
