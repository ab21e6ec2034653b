// One level of the G-buffer pyramid for cold-start searches: each texel averages the valid mirror
// texels of its 2×2 children (positions, and normals renormalised). GBUFFER_FORMAT: the image format.
layout(local_size_x = 8, local_size_y = 8) in;

layout(GBUFFER_FORMAT, binding = 0) uniform readonly image2DArray finerPosition;
layout(GBUFFER_FORMAT, binding = 1) uniform readonly image2DArray finerNormal;
layout(GBUFFER_FORMAT, binding = 2) uniform writeonly image2DArray coarserPosition;
layout(GBUFFER_FORMAT, binding = 3) uniform writeonly image2DArray coarserNormal;

uniform int layer;
uniform ivec2 origin;  // first coarser texel to rebuild: only what changed this frame
uniform ivec2 finerSize;
uniform ivec2 coarserSize;

void main() {
  ivec2 texel = origin + ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, coarserSize))) return;
  vec3 position = vec3(0.0), normal = vec3(0.0);
  float valid = 0.0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      ivec2 child = min(texel * 2 + ivec2(dx, dy), finerSize - 1);
      vec4 p = imageLoad(finerPosition, ivec3(child, layer));
      if (p.w > 0.0) {
        position += p.xyz;
        normal += imageLoad(finerNormal, ivec3(child, layer)).xyz;
        valid += 1.0;
      }
    }
  }
  if (valid > 0.0 && length(normal) > 0.0) {
    imageStore(coarserPosition, ivec3(texel, layer), vec4(position / valid, 1.0));
    imageStore(coarserNormal, ivec3(texel, layer), vec4(normalize(normal), 0.0));
  } else {
    imageStore(coarserPosition, ivec3(texel, layer), vec4(0.0));
    imageStore(coarserNormal, ivec3(texel, layer), vec4(0.0));
  }
}
