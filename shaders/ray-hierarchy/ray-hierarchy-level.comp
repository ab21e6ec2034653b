#version 430 core
// One level of the ray hierarchy (common/ray-hierarchy.glsl) from the level below: the sphere about
// its children's mean centre and the cone about their mean axis that bound them all. Szabo merges
// pairs, then pairs of pairs, which compounds each merge's slack; bounding all children against one
// centre and axis is as safe and tighter.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/ray-hierarchy.glsl"

layout(rgba32f, binding = 0) uniform readonly image2DArray finerSpheres;
layout(rgba32f, binding = 1) uniform readonly image2DArray finerCones;
layout(rgba32f, binding = 2) uniform writeonly image2DArray coarserSpheres;
layout(rgba32f, binding = 3) uniform writeonly image2DArray coarserCones;
uniform int layer;
uniform ivec2 origin;  // first coarser texel to rebuild
uniform ivec2 extent;  // coarser texels to rebuild from there
uniform ivec2 finerSize;
uniform ivec2 coarserSize;

const float kPi = 3.14159265;

void main() {
  if (any(greaterThanEqual(ivec2(gl_GlobalInvocationID.xy), extent))) return;
  ivec2 texel = origin + ivec2(gl_GlobalInvocationID.xy);
  ivec2 low, high;
  rayHierarchyChildren(texel, coarserSize, finerSize, low, high);
  vec3 centre = vec3(0.0), axis = vec3(0.0), firstAxis = vec3(0.0);
  float count = 0.0;
  for (int y = low.y; y <= high.y; ++y) {
    for (int x = low.x; x <= high.x; ++x) {
      vec4 sphere = imageLoad(finerSpheres, ivec3(x, y, layer));
      if (sphere.w < 0.0) continue;
      vec3 childAxis = imageLoad(finerCones, ivec3(x, y, layer)).xyz;
      if (count == 0.0) firstAxis = childAxis;
      centre += sphere.xyz;
      axis += childAxis;
      count += 1.0;
    }
  }
  if (count == 0.0) {
    imageStore(coarserSpheres, ivec3(texel, layer), vec4(0.0, 0.0, 0.0, -1.0));
    imageStore(coarserCones, ivec3(texel, layer), vec4(0.0, 0.0, 0.0, -1.0));
    return;
  }
  centre /= count;
  // Children whose axes cancel (a concave mirror's cells facing each other) keep the first one's.
  axis = length(axis) > 1e-3 * count ? normalize(axis) : firstAxis;
  float radius = 0.0, angle = 0.0;
  for (int y = low.y; y <= high.y; ++y) {
    for (int x = low.x; x <= high.x; ++x) {
      vec4 sphere = imageLoad(finerSpheres, ivec3(x, y, layer));
      if (sphere.w < 0.0) continue;
      vec4 cone = imageLoad(finerCones, ivec3(x, y, layer));
      radius = max(radius, distance(centre, sphere.xyz) + sphere.w);
      angle = max(angle, angleBetween(axis, cone.xyz) + cone.w);
    }
  }
  imageStore(coarserSpheres, ivec3(texel, layer), vec4(centre, radius));
  imageStore(coarserCones, ivec3(texel, layer), vec4(axis, min(angle, kPi)));
}
