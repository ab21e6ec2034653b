// The mirror surface under a frame pixel's centre: the G-buffer covers the frame widened by a margin,
// at its own resolution. Uniforms set by passes::setGBufferPixelMapping.
uniform vec2 marginPixels;     // G-buffer border, frame pixels per side
uniform float texelsPerPixel;  // G-buffer resolution

// Position and unit normal at the pixel centre, bilinear between the four nearest texels of `layer`
// (exactly one texel at one texel per pixel); the nearest texel where some of them are off the
// mirror; false when that one is off it too.
bool gbufferAtPixel(sampler2DArray positions, sampler2DArray normals, int layer, vec2 fragCoord, out vec3 position,
                    out vec3 normal) {
  vec2 coordinate = (fragCoord + marginPixels) * texelsPerPixel - 0.5;  // texel centres at integers
  ivec2 base = ivec2(floor(coordinate));
  vec2 f = coordinate - vec2(base);
  const ivec2 corner[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));
  float weight[4] = float[4]((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  position = vec3(0.0);
  normal = vec3(0.0);
  bool complete = true;
  for (int i = 0; i < 4; ++i) {
    if (weight[i] == 0.0) continue;
    vec4 p = texelFetch(positions, ivec3(base + corner[i], layer), 0);
    complete = complete && p.w > 0.0;
    position += weight[i] * p.xyz;
    normal += weight[i] * texelFetch(normals, ivec3(base + corner[i], layer), 0).xyz;
  }
  if (!complete) {
    ivec3 nearest = ivec3(ivec2(floor(coordinate + 0.5)), layer);
    vec4 p = texelFetch(positions, nearest, 0);
    if (p.w <= 0.0) return false;
    position = p.xyz;
    normal = texelFetch(normals, nearest, 0).xyz;
  }
  normal = normalize(normal);
  return true;
}
