#version 430 core
// Screen-space tessellation of one bicubic Bézier patch (after Hjelmervik & Hagen), chosen afresh
// every frame from the patch's projection: each boundary curve is cut into as many segments as its
// projected control polygon needs for about kPixelsPerSegment pixels a segment and for chords within
// kChordPixels of the curve. The second rule makes silhouettes and tightly curved outlines denser,
// where the projected control polygon bends. An edge's count is computed from that edge's four
// control points alone, symmetrically in their order, so the two patches sharing an edge cut it
// alike and no crack opens between them; the interior takes the finest of its edges and of the
// net's inner rows. A patch whose control net (which holds the patch) lies outside one clip plane
// is dropped.

layout(vertices = 1) out;

uniform mat4 objectToWorld;
uniform mat4 worldToClip;
uniform vec2 viewportPixels;  // the target's size: the pixels a segment is measured in

#include "common/bezier-patch.glsl"

const float kPixelsPerSegment = 8.0;
const float kChordPixels = 0.2;

vec4 clip[16];

float maxSegments() { return float(min(gl_MaxTessGenLevel, 64)); }

// |a × b| in the plane; negating a negates it exactly, so it is the same for either curve direction.
float crossLength(vec2 a, vec2 b) { return abs(a.x * b.y - a.y * b.x); }

// Segments for the cubic whose control points are clip[first + k * stride], k = 0..3.
float curveSegments(int first, int stride) {
  vec4 c0 = clip[first], c1 = clip[first + stride], c2 = clip[first + 2 * stride], c3 = clip[first + 3 * stride];
  if (min(min(c0.w, c1.w), min(c2.w, c3.w)) <= 1e-6) return maxSegments();  // reaches the eye's plane
  vec2 halfViewport = 0.5 * viewportPixels;
  vec2 s0 = c0.xy / c0.w * halfViewport, s1 = c1.xy / c1.w * halfViewport, s2 = c2.xy / c2.w * halfViewport, s3 = c3.xy / c3.w * halfViewport;
  float polygon = (distance(s0, s1) + distance(s2, s3)) + distance(s1, s2);
  // The curve stays within 3/4 of its inner control points' distance from the chord; n equal
  // segments cut that to about 1/n² of it.
  vec2 chord = s3 - s0, middle = 0.5 * (s0 + s3);
  float chordLength = length(chord);
  float bulge = chordLength > 1e-6 ? max(crossLength(chord, s1 - middle), crossLength(chord, s2 - middle)) / chordLength
                                   : max(distance(s1, middle), distance(s2, middle));
  float segments = max(polygon / kPixelsPerSegment, sqrt(0.75 * bulge / kChordPixels));
  return clamp(ceil(segments), 1.0, maxSegments());
}

// True when every control point lies beyond the same clip plane: the patch is out of view.
bool outsideOnePlane() {
  vec3 aboveLow = vec3(-1e30), belowHigh = vec3(-1e30);  // max over the points of w ± x, y, z
  for (int i = 0; i < 16; ++i) {
    aboveLow = max(aboveLow, clip[i].xyz + clip[i].w);
    belowHigh = max(belowHigh, clip[i].w - clip[i].xyz);
  }
  return any(lessThan(aboveLow, vec3(0.0))) || any(lessThan(belowHigh, vec3(0.0)));
}

void main() {
  mat4 objectToClip = worldToClip * objectToWorld;
  int first = 16 * gl_PrimitiveID;
  for (int i = 0; i < 16; ++i) clip[i] = objectToClip * vec4(patchPoints[first + i].xyz, 1.0);
  if (outsideOnePlane()) {
    for (int i = 0; i < 4; ++i) gl_TessLevelOuter[i] = 0.0;  // a zero outer level drops the patch
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
    return;
  }
  // Outer levels of the quad domain: 0 the edge u = 0, 1 v = 0, 2 u = 1, 3 v = 1.
  gl_TessLevelOuter[0] = curveSegments(0, 4);
  gl_TessLevelOuter[1] = curveSegments(0, 1);
  gl_TessLevelOuter[2] = curveSegments(3, 4);
  gl_TessLevelOuter[3] = curveSegments(12, 1);
  gl_TessLevelInner[0] = max(max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]), max(curveSegments(4, 1), curveSegments(8, 1)));
  gl_TessLevelInner[1] = max(max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]), max(curveSegments(1, 4), curveSegments(2, 4)));
}
