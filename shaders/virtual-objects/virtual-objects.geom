#version 430 core
// Keeps a virtual triangle only where it can be a true reflection, so none smears across the mirror:
// every corner has a reflection point, at least one is not hidden (region C), and the corners'
// mirror normals are less than 90° apart: corners on far sides of a mirror, or on the inside and
// outside of a bowl, belong to different reflections that one flat triangle cannot join.
// On a concave or saddle part every corner must have its reflection point there: a corner without
// one has no place on the part from which the triangle could be completed (on a convex part it is
// mirrored just beyond the silhouette, where the triangle is cut off).
#include "common/reflected-vertex.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionNormal;
  flat int flags;
} inVertex[];

uniform int everyCornerReflected;  // 1 on concave and saddle parts
uniform vec2 frameSize;            // pixels
uniform vec4 mirrorRect;           // the part's bounds on screen in frame pixels (GL origin): low x, y, high x, y

// The triangle is widened by this much on screen: its virtual image is right to the tessellation
// threshold, and the fragment shader keeps only pixels whose reflected ray really meets it, so every
// pixel the triangle shows in must be proposed (conservative rasterization). A triangle smaller than
// that on screen is widened by its own size: its corners' images are exact, so its true image lies
// within about its size of them.
const float kDilationPixels = 2.0;
const float kMaxCornerShift = 8.0;  // × kDilationPixels: sharp corners move no further

out FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  flat vec3 corner[3];  // the triangle in world space: each fragment's reflected ray is tested against it
} outFragment;

void main() {
  int allFlags = inVertex[0].flags | inVertex[1].flags | inVertex[2].flags;
  int commonFlags = inVertex[0].flags & inVertex[1].flags & inVertex[2].flags;
  if ((allFlags & kReflectionUnsolved) != 0 || (commonFlags & kReflectionHidden) != 0) return;
  if (everyCornerReflected != 0 && (allFlags & kReflectionHidden) != 0) return;
  for (int i = 0; i < 3; ++i)
    if (dot(inVertex[i].reflectionNormal, inVertex[(i + 1) % 3].reflectionNormal) < 0.0) return;
  // Each corner moves away from the other two so that every edge moves out by the dilation;
  // corners behind the eye (w <= 0) leave the triangle as it is.
  vec4 position[3] = vec4[3](gl_in[0].gl_Position, gl_in[1].gl_Position, gl_in[2].gl_Position);
  if (position[0].w > 0.0 && position[1].w > 0.0 && position[2].w > 0.0) {
    vec2 screen[3];
    for (int i = 0; i < 3; ++i) screen[i] = position[i].xy / position[i].w * 0.5 * frameSize;
    float dilation = min(kDilationPixels, max(max(distance(screen[0], screen[1]), distance(screen[1], screen[2])),
                                              distance(screen[2], screen[0])));
    // Wholly beside the part on screen, even widened: no pixel to propose (and no fragment to test).
    vec2 low = min(screen[0], min(screen[1], screen[2])) + 0.5 * frameSize - kMaxCornerShift * dilation;
    vec2 high = max(screen[0], max(screen[1], screen[2])) + 0.5 * frameSize + kMaxCornerShift * dilation;
    if (any(lessThan(high, mirrorRect.xy)) || any(greaterThan(low, mirrorRect.zw))) return;
    float winding = sign((screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) - (screen[1].y - screen[0].y) * (screen[2].x - screen[0].x));
    if (winding != 0.0) {
      vec2 outward[3];  // unit normal of edge i (corner i → i + 1), pointing away from the triangle
      for (int i = 0; i < 3; ++i) {
        vec2 edge = normalize(screen[(i + 1) % 3] - screen[i]);
        outward[i] = winding * vec2(edge.y, -edge.x);
      }
      for (int i = 0; i < 3; ++i) {
        // Corner i lies on edges i and i - 1: move it along both normals' bisector.
        vec2 a = outward[i], b = outward[(i + 2) % 3];
        vec2 bisector = a + b;
        float along = dot(bisector, a);
        vec2 shift = along > 1e-3 ? bisector / along : a + b;
        if (length(shift) > kMaxCornerShift) shift *= kMaxCornerShift / length(shift);
        position[i].xy += dilation * shift / (0.5 * frameSize) * position[i].w;
      }
    }
  }
  for (int i = 0; i < 3; ++i) {
    outFragment.worldPosition = inVertex[i].worldPosition;
    outFragment.worldNormal = inVertex[i].worldNormal;
    outFragment.surfaceUv = inVertex[i].surfaceUv;
    for (int k = 0; k < 3; ++k) outFragment.corner[k] = inVertex[k].worldPosition;
    gl_Position = position[i];
    EmitVertex();
  }
  EndPrimitive();
}
