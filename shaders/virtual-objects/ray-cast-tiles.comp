#version 430 core
// Where a ray-cast part's objects can appear: per 8×8 tile of the part's pixels (one invocation per
// tile, no shared memory), a ball around its rays' origins and a cone around their directions; each
// object whose bounding sphere such a ray could reach gets the tile appended to its list, and its
// indirect draw one instance more. The cast then runs only on its objects' tiles instead of every
// pixel of the part once per object.
// Conservative: a ray from anywhere in the origin ball, within the cone, that meets the object's
// sphere passes within (object radius + ball radius) of it as seen from the ball's centre.
#include "virtual-objects/cast-ray.glsl"

layout(local_size_x = 64) in;
const int kTile = 8;  // pixels per side: VirtualObjectsPass's kCastTile

uniform ivec2 firstTile;   // the tile of the part's low pixel corner; tile (x, y) covers pixels 8x..8x+7
uniform ivec2 tileExtent;  // tiles across and up the part's pixels
uniform int firstObject;     // the part's first sphere and draw command
uniform int objectCount;
uniform uint firstEntry;     // the part's first tile-list entry
uniform uint tileCapacity;   // tiles each object's list holds: every tile of the part

layout(std430, binding = 10) readonly buffer CastObjects {
  vec4 objectSphere[];  // world centre, radius: in each part's draw order
};
struct DrawCommand {
  uint count, instances, first, baseInstance;
};
layout(std430, binding = 11) buffer CastDraws {
  DrawCommand castDraw[];  // one per object; instances counts its tiles
};
layout(std430, binding = 12) writeonly buffer CastTiles {
  uint castTile[];  // the part's object k's tiles at firstEntry + k * tileCapacity: x | y << 16
};

// Whether a ray from within (centre, radius), its direction within `spread` radians of `axis`, may meet `sphere`.
bool tileMayReach(vec3 centre, float radius, vec3 axis, float spread, vec4 sphere) {
  vec3 toObject = sphere.xyz - centre;
  float distance = length(toObject);
  // Float slack relative to the lengths involved, so far tiles keep as much margin as near ones.
  float reach = (sphere.w + radius) * 1.001 + 1e-5 * (distance + length(centre));
  if (distance <= reach) return true;
  float towardsObject = acos(clamp(dot(axis, toObject) / distance, -1.0, 1.0));
  return towardsObject <= spread + asin(reach / distance) + 1e-3;
}

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= tileExtent.x * tileExtent.y) return;
  ivec2 tile = firstTile + ivec2(index % tileExtent.x, index / tileExtent.x);
  // The part's pixels are its nearest-hit rectangle; each tile starts its own with no hit.
  ivec2 low = max(tile * kTile, hitPixelLow), high = min(tile * kTile + kTile, hitPixelHigh);
  // Boxes around the origins and the (unit) directions, in one pass over the tile's pixels.
  vec3 originLow = vec3(1e30), originHigh = vec3(-1e30), directionLow = vec3(2.0), directionHigh = vec3(-2.0);
  bool any = false;
  for (int y = low.y; y < high.y; ++y) {
    for (int x = low.x; x < high.x; ++x) {
      nearestHit[nearestHitEntry(ivec2(x, y))] = floatBitsToUint(1e30);
      vec3 origin, incoming, direction;
      if (!castRayAtPixel(vec2(x, y) + 0.5, origin, incoming, direction)) continue;
      any = true;
      originLow = min(originLow, origin);
      originHigh = max(originHigh, origin);
      directionLow = min(directionLow, direction);
      directionHigh = max(directionHigh, direction);
    }
  }
  if (!any) return;
  vec3 centre = 0.5 * (originLow + originHigh);
  float radius = 0.5 * length(originHigh - originLow);
  // Every direction d in the box lies within its half-diagonal h of the box centre c: at most
  // asin(h / |c|) from c's direction when h < |c|; otherwise the cone is every direction.
  vec3 middle = 0.5 * (directionLow + directionHigh);
  float halfDiagonal = 0.5 * length(directionHigh - directionLow), middleLength = length(middle);
  bool narrow = halfDiagonal < 0.999 * middleLength;
  vec3 axis = narrow ? middle / middleLength : vec3(0.0, 0.0, 1.0);
  float spread = narrow ? asin(halfDiagonal / middleLength) : 3.14159265;
  uint tileEntry = uint(tile.x) | (uint(tile.y) << 16);
  for (int object = 0; object < objectCount; ++object) {
    if (!tileMayReach(centre, radius, axis, spread, objectSphere[firstObject + object])) continue;
    uint slot = atomicAdd(castDraw[firstObject + object].instances, 1u);
    castTile[firstEntry + uint(object) * tileCapacity + slot] = tileEntry;
  }
}
