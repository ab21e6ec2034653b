// What every search strategy shares: the mirror's G-buffer layer searched, the eye, the vertex whose
// reflection is sought, how well a texel reflects it (N·B) and where a world point lands on the G-buffer.
#include "common/reflection.glsl"
#include "common/reflected-vertex.glsl"

uniform sampler2DArray gbufferPosition;  // w > 0 on mirror texels
uniform sampler2DArray gbufferNormal;
uniform int layer;
uniform vec3 eyePosition;
uniform mat4 gbufferWorldToClip;  // the eye's projection widened by the G-buffer margin

const float kInvalid = -3.0;   // below any reflectionObjective

const ivec2 kNeighbours[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),  // crosshair first
                                      ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));

vec3 vertexWorld;

// GL mip sizes: halved, rounded down, at least 1. Not textureSize(sampler, level): with a level that
// differs between invocations it returned wrong sizes on llvmpipe (the ray hierarchy lost its way).
ivec2 mipLevelSize(ivec2 base, int level) { return max(base >> level, ivec2(1)); }

float objectiveAt(ivec2 texel, int level) {
  ivec2 size = mipLevelSize(textureSize(gbufferPosition, 0).xy, level);
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return kInvalid;
  vec4 p = texelFetch(gbufferPosition, ivec3(texel, layer), level);
  if (p.w <= 0.0) return kInvalid;
  return reflectionObjective(p.xyz, texelFetch(gbufferNormal, ivec3(texel, layer), level).xyz, eyePosition,
                             vertexWorld);
}

// Where a world point lands on the G-buffer, in texels (centres at +0.5); w ≤ 0 behind the eye.
vec3 gbufferCoordinateOf(vec3 world) {
  vec4 clip = gbufferWorldToClip * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec3(0.0, 0.0, -1.0);
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * vec2(textureSize(gbufferPosition, 0).xy), 1.0);
}
