// A virtual triangle from its three corners (world position, normal, uv, virtual position and search
// result each): dropped where it cannot be one reflection (common/reflectable-triangle.glsl), so
// none smears across the mirror, or lies beside the mirror on screen; else widened. Used by the
// geometry shader for objects drawn from their meshes (their vertices shaded once and shared), and
// by the vertex shader of tessellated triangles, which reads all three corners of its triangle
// itself and needs no geometry shader (on a CPU rasterizer one cost ~2 µs a triangle).
#include "common/reflectable-triangle.glsl"

uniform mat4 worldToClip;          // far plane pushed out: virtual vertices lie up to a path length away
uniform int everyCornerReflected;  // 1 on concave and saddle parts
uniform vec2 frameSize;            // pixels
uniform vec4 mirrorRect;           // the part's bounds on screen in frame pixels (GL origin): low x, y, high x, y
uniform int drawAsPlaced;          // 1: the triangle is shaded where it lies (virtual-objects.frag), so not widened

// The triangle is widened by this much on screen: its virtual image is right to the tessellation
// threshold, and the fragment shader keeps only pixels whose reflected ray really meets it, so every
// pixel the triangle shows in must be proposed (conservative rasterization). A triangle smaller than
// that on screen is widened by its own size: its corners' images are exact, so its true image lies
// within about its size of them.
const float kDilationPixels = 2.0;
const float kMaxCornerShift = 8.0;  // × the widening: sharp corners move no further

out FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  flat vec3 corner[3];  // the triangle in world space: each fragment's reflected ray is tested against it
} outFragment;

// Clip positions of the triangle's corners, widened; false when the triangle is not drawn.
bool placeVirtualTriangle(TessellatedVertex c[3], out vec4 position[3]) {
  for (int i = 0; i < 3; ++i) position[i] = worldToClip * vec4(c[i].virtualFlags.xyz, 1.0);
  if (!reflectableTriangle(c, everyCornerReflected != 0)) return false;
  // Each corner moves away from the other two so that every edge moves out by the widening;
  // corners behind the eye (w <= 0) leave the triangle as it is.
  if (drawAsPlaced != 0 || position[0].w <= 0.0 || position[1].w <= 0.0 || position[2].w <= 0.0) return true;
  vec2 screen[3];
  for (int i = 0; i < 3; ++i) screen[i] = position[i].xy / position[i].w * 0.5 * frameSize;
  float dilation = min(kDilationPixels, max(max(distance(screen[0], screen[1]), distance(screen[1], screen[2])),
                                            distance(screen[2], screen[0])));
  // Wholly beside the part on screen, even widened: no pixel to propose (and no fragment to test).
  vec2 low = min(screen[0], min(screen[1], screen[2])) + 0.5 * frameSize - kMaxCornerShift * dilation;
  vec2 high = max(screen[0], max(screen[1], screen[2])) + 0.5 * frameSize + kMaxCornerShift * dilation;
  if (any(lessThan(high, mirrorRect.xy)) || any(greaterThan(low, mirrorRect.zw))) return false;
  float winding = sign((screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) - (screen[1].y - screen[0].y) * (screen[2].x - screen[0].x));
  if (winding == 0.0) return true;
  vec2 outward[3];  // unit normal of edge i (corner i → i + 1), pointing away from the triangle
  for (int i = 0; i < 3; ++i) {
    vec2 edge = normalize(screen[(i + 1) % 3] - screen[i]);
    outward[i] = winding * vec2(edge.y, -edge.x);
  }
  for (int i = 0; i < 3; ++i) {
    // Corner i lies on edges i and i − 1: move it along both normals' bisector.
    vec2 a = outward[i], b = outward[(i + 2) % 3];
    vec2 bisector = a + b;
    float along = dot(bisector, a);
    vec2 shift = along > 1e-3 ? bisector / along : a + b;
    if (length(shift) > kMaxCornerShift) shift *= kMaxCornerShift / length(shift);
    position[i].xy += dilation * shift / (0.5 * frameSize) * position[i].w;
  }
  return true;
}

// Corner k's outputs for the fragment shader (gl_Position is the caller's).
void writeVirtualCorner(TessellatedVertex c[3], int k) {
  outFragment.worldPosition = c[k].positionU.xyz;
  outFragment.worldNormal = c[k].normalV.xyz;
  outFragment.surfaceUv = vec2(c[k].positionU.w, c[k].normalV.w);
  for (int i = 0; i < 3; ++i) outFragment.corner[i] = c[i].positionU.xyz;
}
