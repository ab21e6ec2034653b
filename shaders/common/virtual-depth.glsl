// Depth of what a mirror pixel shows, placed on the eye's ray through the mirror point a whole path
// length away: exact hits in [0, 0.5), near misses (a ray passing just outside the triangle that
// proposed the pixel) in [0.5, 1), so any exact hit wins over every near miss; 1 stays the cleared
// far plane, where the mirror shows the background.
#include "common/clip-depth.glsl"

float virtualDepth(mat4 worldToClip, vec3 virtualPoint, bool nearMiss) {
  return clipDepth(worldToClip, virtualPoint) * (nearMiss ? 1.0 : 1.0);
}
