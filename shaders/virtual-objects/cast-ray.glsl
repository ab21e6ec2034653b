// The reflected ray a ray-cast pixel follows: from the mirror's G-buffer point under the pixel,
// lifted off the surface on the ray's side. Shared by the cast itself (ray-cast.frag) and the tile
// classification that decides where each object's cast is drawn (ray-cast-tiles.comp), so both see
// the same rays. Uniforms set by passes::VirtualObjectsPass::setCastRay.
#include "common/gbuffer-texel.glsl"

uniform sampler2DArray gbufferPosition;  // w > 0 on this part's texels
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform vec3 eyePosition;
// How far the G-buffer point may lie off the true surface: per metre from the eye (bilinear between
// texels that are not at the pixel centre) plus a constant (RGBA16F rounding). The ray starts that
// far out on its own side, or a mirror seeing itself would meet its own surface where it starts.
uniform float liftPerMetre;
uniform float lift;

// False where the pixel shows no point of this part.
bool castRayAtPixel(vec2 fragCoord, out vec3 surface, out vec3 incoming, out vec3 reflected) {
  vec3 normal;
  if (!gbufferAtPixel(gbufferPosition, gbufferNormal, layer, fragCoord, surface, normal)) return false;
  incoming = normalize(surface - eyePosition);
  reflected = reflect(incoming, normal);
  surface += (lift + liftPerMetre * length(surface - eyePosition)) * sign(dot(reflected, normal)) * normal;
  return true;
}

// Per pixel of a tiled ray-cast part, the nearest hit distance along its ray of the objects cast so
// far (float bits: positive floats order like their bits), reset by the tile classification. It only
// prunes traversals, so it is read without `coherent` (faster on llvmpipe): a stale value costs time,
// never a wrong pixel, as the depth test still keeps the nearest fragment. Pixels outside the part's rectangle, or firstHit < 0, have no bound.
uniform ivec2 hitPixelLow;
uniform ivec2 hitPixelHigh;
uniform int firstHit;

layout(std430, binding = 13) buffer NearestHits {
  uint nearestHit[];
};

// The entry of `pixel`, or -1 where it has none.
int nearestHitEntry(ivec2 pixel) {
  if (firstHit < 0 || any(lessThan(pixel, hitPixelLow)) || any(greaterThanEqual(pixel, hitPixelHigh))) return -1;
  return firstHit + (pixel.y - hitPixelLow.y) * (hitPixelHigh.x - hitPixelLow.x) + (pixel.x - hitPixelLow.x);
}
