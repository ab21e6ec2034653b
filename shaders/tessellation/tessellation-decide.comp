#version 440 core
// Round step 3, per working triangle: which edges split, from its classification and the errors of
// its searched edges, and how many triangles it becomes, counted into its run.
#include "tessellation/tessellation-round.glsl"

layout(local_size_x = TESSELLATION_GROUP_SIZE) in;

void main() {
  uint triangle, local, run;
  if (!roundTriangle(triangle, local, run)) return;
  int requested = splits[triangle].mask.y & 7, nearBits = (splits[triangle].mask.y >> 3) & 7;
  vec3 error = splits[triangle].error.xyz;
  int mask = 0;
  if (pixelMetric != 0) {
    float worst = max(error[0], max(error[1], error[2]));
    for (int e = 0; e < 3; ++e) {
      bool near = (nearBits & (1 << e)) != 0;
      if ((requested & (1 << e)) != 0 && (crackFree != 0 ? exceeds(error[e]) || near : exceeds(worst) || nearBits != 0) &&
          solved(splits[triangle].midpoint[e]))
        mask |= 1 << e;
    }
  } else {
    mask = requested;  // the angle metric asked for exactly the edges that split
  }
  splits[triangle].mask.x = mask;
  const uint kChildren[4] = uint[4](0u, 2u, 3u, 4u);  // by number of split edges
  if (mask != 0) atomicAdd(runs[run].children, kChildren[bitCount(mask)]);
  else if ((splits[triangle].mask.y & kDrawable) != 0) atomicAdd(runs[run].unsplit, 1u);  // the others are dropped
}
