#version 430 core
#include "common/shading.glsl"
#include "common/gbuffer-texel.glsl"

in FragmentData {
  vec3 worldPosition;
  vec3 worldNormal;
  vec2 surfaceUv;
  vec3 reflectionPoint;
} inFragment;

uniform float reflectivity;  // the mirror's; its surface colour was already weighted by 1 − reflectivity
uniform int depthOnly;       // 1 in the depth pre-pass: only the nearest virtual surface is shaded
uniform sampler2DArray gbufferPosition;  // w > 0 on this part's texels
uniform sampler2DArray gbufferNormal;
uniform int layer;           // the part's G-buffer layer
uniform int partMask;        // 1: the mirror has several parts, and this one shows only on its own texels
uniform int rayCheck;        // 1 on concave and saddle parts: fragments must lie on this pixel's reflected ray
uniform vec3 eyePosition;

// A fragment whose object point lies further than this (sine of the angle) off the pixel's
// reflected ray belongs to a triangle stretched across two images of a concave part.
const float kOffRaySine = 0.2;
// The object point is moved onto the pixel's reflected ray only by a small step (a share of its
// distance from the mirror) and where the ray meets the surface's plane at more than a grazing angle.
const float kMaxCorrection = 0.05;
const float kMinIncidence = 0.05;

layout(location = 0) out vec4 outColor;

void main() {
  // The object point and uv are affine over the triangle: their screen derivatives (taken before any
  // discard, in uniform control flow) map a step in the surface's plane to a step in uv.
  vec3 point = inFragment.worldPosition;
  vec2 uv = inFragment.surfaceUv;
  vec3 pointDx = dFdx(point), pointDy = dFdy(point);
  vec2 uvDx = dFdx(uv), uvDy = dFdy(uv);

  ivec3 texel = ivec3(gbufferTexelAt(gl_FragCoord.xy), layer);
  vec4 surface = texelFetch(gbufferPosition, texel, 0);
  // Each part of a mirror shows its own reflection: its virtual triangles end at its outline.
  if (partMask != 0 && surface.w <= 0.0) discard;
  if (surface.w > 0.0) {
    vec3 reflected = reflect(normalize(surface.xyz - eyePosition), normalize(texelFetch(gbufferNormal, texel, 0).xyz));
    vec3 toObject = point - surface.xyz;
    if (rayCheck != 0 && (length(cross(reflected, toObject)) > kOffRaySine * length(toObject) || dot(reflected, toObject) <= 0.0))
      discard;
    // The rasterized triangle is flat between its corners' exact reflections, so inside it the object
    // point is off by up to the tessellation threshold, many checker cells where a floor is seen
    // nearly edge-on. The pixel's own reflected ray meets the surface's tangent plane at the point the
    // ray tracer shades: move there (exact for flat surfaces), and the uv with it.
    vec3 normal = normalize(inFragment.worldNormal);
    float incidence = dot(reflected, normal);
    if (abs(incidence) > kMinIncidence) {
      vec3 step = reflected * (dot(toObject, normal) / incidence) - toObject;
      mat2 gram = mat2(dot(pointDx, pointDx), dot(pointDx, pointDy), dot(pointDx, pointDy), dot(pointDy, pointDy));
      if (length(step) < kMaxCorrection * length(toObject) && abs(determinant(gram)) > 1e-30) {
        vec2 screenStep = inverse(gram) * vec2(dot(step, pointDx), dot(step, pointDy));
        point += step;
        uv += screenStep.x * uvDx + screenStep.y * uvDy;
      }
    }
  }
  if (depthOnly != 0) {
    outColor = vec4(0.0);
    return;
  }
  outColor = vec4(reflectivity * shadeSurface(point, inFragment.worldNormal, uv, inFragment.reflectionPoint), 1.0);
}
