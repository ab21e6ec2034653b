#version 430 core
// A virtual triangle only proposes which pixels its object triangle may show in: each fragment
// casts its pixel's reflected ray (from the mirror's G-buffer point and normal, as the ray tracer
// reflects) against the triangle itself and keeps the exact hit, shaded there and placed at its
// exact path length. The rasterized triangle is flat between its corners' reflections, so without
// this the object point inside it is off by up to the tessellation threshold (many checker cells
// where a floor is seen nearly edge-on), and on a concave part a triangle can stretch across two
// images; with it, only coverage (which pixels a triangle is tried at) remains approximate.
#include "common/clip-depth.glsl"
#include "common/gbuffer-texel.glsl"
#include "common/shading.glsl"

in FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  flat vec3 corner[3];
} inFragment;

uniform float reflectivity;  // the mirror's; its surface colour was already weighted by 1 − reflectivity
uniform sampler2DArray gbufferPosition;  // w > 0 on this part's texels
uniform sampler2DArray gbufferNormal;
uniform int layer;           // the part's G-buffer layer
uniform vec3 eyePosition;
uniform mat4 worldToClip;    // the virtual objects' projection (far plane pushed out)
// 1: the papers' rendering, each fragment shaded where the virtual triangle puts it (Ofek & Rappoport's
// explosion map draws so), only kept to the part's own pixels; 0: the exact hit below.
uniform int drawAsPlaced;
uniform vec3 viewForward;    // the eye's view axis (world, unit)
uniform float pixelAngle;    // radians one pixel spans on the view axis: the ray cone's spread

// A hit this share of the triangle's shortest edge outside it still counts: float rounding on the
// edge two triangles share must not leave a pixel to neither.
const float kEdgeTolerance = 1e-4;

layout(location = 0) out vec4 outColor;

void main() {
  // Position, normal and uv are affine over the triangle: their screen derivatives (taken before any
  // discard, in uniform control flow) carry them from the rasterized point to the exact hit.
  vec3 point = inFragment.worldPosition;
  vec3 pointDx = dFdx(point), pointDy = dFdy(point);
  vec3 normalDx = dFdx(inFragment.worldNormal), normalDy = dFdy(inFragment.worldNormal);
  vec2 uvDx = dFdx(inFragment.surfaceUv), uvDy = dFdy(inFragment.surfaceUv);
  // The object triangle's uv per metre: both are affine over it, so the ratio of their screen area
  // elements is exact, however the virtual triangle distorts them. Its texture footprint comes from
  // the reflected ray's cone, as for ray-cast pixels and the reference, not from these derivatives
  // (a virtual triangle's screen size says little of its object's reflected size).
  float areaScale = length(cross(pointDx, pointDy));
  float uvScale = areaScale > 0.0 ? sqrt(abs(uvDx.x * uvDy.y - uvDx.y * uvDy.x) / areaScale) : 0.0;
  vec3 objectNormal = normalize(cross(inFragment.corner[1] - inFragment.corner[0], inFragment.corner[2] - inFragment.corner[0]));

  vec3 surface, surfaceNormal;
  // Off this part of the mirror (or its surface): not this part's pixel.
  if (!gbufferAtPixel(gbufferPosition, gbufferNormal, layer, gl_FragCoord.xy, surface, surfaceNormal)) discard;
  vec3 incoming = normalize(surface - eyePosition);
  vec3 reflected = reflect(incoming, surfaceNormal);
  float eyeDepthPerLength = dot(incoming, viewForward), eyeDistance = length(surface - eyePosition);
  if (drawAsPlaced != 0) {
    gl_FragDepth = gl_FragCoord.z;
    vec3 toPoint = point - surface;
    float footprint = pixelFootprint(eyeDistance + length(toPoint), eyeDepthPerLength, pixelAngle, dot(normalize(toPoint), objectNormal));
    outColor = vec4(reflectivity * shadeSurfaceOver(point, normalize(inFragment.worldNormal), inFragment.surfaceUv, footprint * uvScale, surface), 1.0);
    return;
  }

  vec3 a = inFragment.corner[0], edge1 = inFragment.corner[1] - a, edge2 = inFragment.corner[2] - a;
  vec3 plane = cross(edge1, edge2);
  float incidence = dot(reflected, plane);
  if (incidence == 0.0) discard;
  float distance = dot(a - surface, plane) / incidence;
  if (!(distance > 0.0)) discard;
  vec3 hit = surface + distance * reflected;
  // Barycentric weights of the hit, and how far outside the triangle it lies in world units.
  float area2 = dot(plane, plane);
  vec3 weights;
  weights.y = dot(cross(hit - a, edge2), plane) / area2;
  weights.z = dot(cross(edge1, hit - a), plane) / area2;
  weights.x = 1.0 - weights.y - weights.z;
  float twiceArea = sqrt(area2);
  vec3 heights = twiceArea / vec3(length(inFragment.corner[2] - inFragment.corner[1]), length(edge2), length(edge1));
  float outside = max(0.0, max(max(-weights.x * heights.x, -weights.y * heights.y), -weights.z * heights.z));
  if (outside > kEdgeTolerance * twiceArea / max(max(heights.x, heights.y), heights.z)) discard;

  gl_FragDepth = clipDepth(worldToClip, eyePosition + (length(surface - eyePosition) + distance) * incoming);
  // Carry normal and uv from the rasterized point to the hit, through the screen step between them.
  vec3 step = hit - point;
  mat2 gram = mat2(dot(pointDx, pointDx), dot(pointDx, pointDy), dot(pointDx, pointDy), dot(pointDy, pointDy));
  vec2 screenStep = abs(determinant(gram)) > 1e-30 ? inverse(gram) * vec2(dot(step, pointDx), dot(step, pointDy)) : vec2(0.0);
  vec3 normal = inFragment.worldNormal + screenStep.x * normalDx + screenStep.y * normalDy;
  vec2 uv = inFragment.surfaceUv + screenStep.x * uvDx + screenStep.y * uvDy;
  float footprint = pixelFootprint(eyeDistance + distance, eyeDepthPerLength, pixelAngle, dot(reflected, objectNormal));
  outColor = vec4(reflectivity * shadeSurfaceOver(hit, normal, uv, footprint * uvScale, surface), 1.0);
}
