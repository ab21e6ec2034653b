#version 430 core
// One object seen in a mirror part by casting each pixel's reflected ray (from the G-buffer point,
// as the ray tracer does with one bounce) against the object's mesh through its hierarchy, and
// keeping the nearest hit, shaded there at the depth of that reflection like a virtual object.
// Serves three cases: the mirror meeting itself (a bowl's inside reflecting its far wall: it shows
// its own colour there, and what lies behind it in its own reflection stays hidden), the objects of
// a part the frame plan ray-casts instead of searching (drawn on the tiles ray-cast-tiles.comp lists
// for each, ray-cast-tile.vert, or over the whole part), and the pixels of a searched part that no
// virtual object landed on (drawn as points, uncovered-pixel.vert).
#include "common/clip-depth.glsl"
#include "common/shading.glsl"
#include "common/triangle-bvh.glsl"
#include "virtual-objects/cast-ray.glsl"

uniform mat4 objectToWorld;
uniform mat4 worldToObject;
uniform mat3 normalToWorld;
uniform mat4 worldToClip;     // the virtual objects' projection (far plane pushed out)
uniform float minDistance;    // object space: nearer hits are the surface the ray starts on
uniform float reflectivity;  // the mirror's
uniform vec3 viewForward;    // the eye's view axis (world, unit)
uniform float pixelAngle;    // radians one pixel spans on the view axis: the ray cone's spread

layout(std430, binding = 6) readonly buffer MeshVertices {
  float meshVertex[];  // scene::Vertex: position xyz, normal xyz, uv — 8 floats
};
layout(std430, binding = 7) readonly buffer MeshIndices {
  uint meshIndex[];
};

layout(location = 0) out vec4 outColor;

vec3 attribute3(uint vertex, uint offset) {
  uint at = 8u * vertex + offset;
  return vec3(meshVertex[at], meshVertex[at + 1u], meshVertex[at + 2u]);
}

void main() {
  vec3 surface, incoming, reflected;
  if (!castRayAtPixel(gl_FragCoord.xy, surface, incoming, reflected)) discard;
  float distance;
  uint triangle;
  vec2 barycentric;
  // The object-space ray is the world ray transformed, so distances along both are the same.
  int hitEntry = nearestHitEntry(ivec2(gl_FragCoord.xy));
  float nearestSoFar = hitEntry < 0 ? 1e30 : uintBitsToFloat(nearestHit[hitEntry]);
  if (!intersectBvh((worldToObject * vec4(surface, 1.0)).xyz, mat3(worldToObject) * reflected, minDistance, nearestSoFar,
                    distance, triangle, barycentric))
    discard;
  if (hitEntry >= 0) atomicMin(nearestHit[hitEntry], floatBitsToUint(distance));
  uint i0 = meshIndex[3u * triangle], i1 = meshIndex[3u * triangle + 1u], i2 = meshIndex[3u * triangle + 2u];
  vec3 weights = vec3(1.0 - barycentric.x - barycentric.y, barycentric);
  vec3 position = weights.x * attribute3(i0, 0u) + weights.y * attribute3(i1, 0u) + weights.z * attribute3(i2, 0u);
  vec3 hitNormal = weights.x * attribute3(i0, 3u) + weights.y * attribute3(i1, 3u) + weights.z * attribute3(i2, 3u);
  vec2 uv0 = vec2(meshVertex[8u * i0 + 6u], meshVertex[8u * i0 + 7u]);
  vec2 uv1 = vec2(meshVertex[8u * i1 + 6u], meshVertex[8u * i1 + 7u]);
  vec2 uv2 = vec2(meshVertex[8u * i2 + 6u], meshVertex[8u * i2 + 7u]);
  vec2 uv = weights.x * uv0 + weights.y * uv1 + weights.z * uv2;
  vec3 hit = (objectToWorld * vec4(position, 1.0)).xyz;
  // On the eye's ray through the mirror point, a whole path length away, like a virtual vertex.
  float path = length(surface - eyePosition) + length(hit - surface);
  gl_FragDepth = clipDepth(worldToClip, eyePosition + path * incoming);
  // The texture's footprint from the ray cone (a traced pixel has no screen derivatives).
  float footprint = 0.0;
  if (materialHasTexture != 0) {
    mat3 toWorld = mat3(objectToWorld);
    vec3 p0 = toWorld * attribute3(i0, 0u), p1 = toWorld * attribute3(i1, 0u), p2 = toWorld * attribute3(i2, 0u);
    float cosine = dot(reflected, normalize(cross(p1 - p0, p2 - p0)));
    footprint = pixelFootprint(path, dot(incoming, viewForward), pixelAngle, cosine) * uvPerMetre(p0, p1, p2, uv0, uv1, uv2);
  }
  outColor = vec4(reflectivity * shadeSurfaceOver(hit, normalToWorld * hitNormal, uv, footprint, surface), 1.0);
}
