// What a tessellation round decides for one working triangle, for the emit pass: which edges split
// and the new vertex on each (edge e runs from corner e to corner e + 1).
#include "common/tessellated-vertex.glsl"

struct EdgeSplit {
  TessellatedVertex midpoint[3];
  ivec4 mask;  // x: bit e set when edge e splits; y: edges searched (bits 0-2), long beside the mirror
               // (bits 3-5), and bit 6 when the triangle is drawable unsplit
  vec4 error;  // xyz: each searched edge's error (pixels, or Szabo's angle error)
};
