// Whether three corners with their search results can make one virtual triangle: every corner has a
// reflection point, at least one is not hidden (region C), and the corners' mirror normals are less
// than 90° apart (corners on far sides of a mirror, or on the inside and outside of a bowl, belong to
// different reflections that one flat triangle cannot join). `everyCornerReflected` (concave and
// saddle parts): no corner may be hidden, since a corner without a reflection point has no place on
// the part from which the triangle could be completed (on a convex part it is mirrored just beyond
// the silhouette, where the triangle is cut off). The virtual-objects pass draws by it and
// tessellation leaves out of its finished list what it would not draw.
#include "common/tessellated-vertex.glsl"

bool reflectableTriangle(TessellatedVertex c[3], bool everyCornerReflected) {
  int flags[3] = int[3](int(c[0].virtualFlags.w), int(c[1].virtualFlags.w), int(c[2].virtualFlags.w));
  int allFlags = flags[0] | flags[1] | flags[2];
  if ((allFlags & kReflectionUnsolved) != 0 || (flags[0] & flags[1] & flags[2] & kReflectionHidden) != 0) return false;
  if (everyCornerReflected && (allFlags & kReflectionHidden) != 0) return false;
  for (int i = 0; i < 3; ++i)
    if (dot(c[i].normalTexelY.xyz, c[(i + 1) % 3].normalTexelY.xyz) < 0.0) return false;
  return true;
}
