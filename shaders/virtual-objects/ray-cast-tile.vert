#version 430 core
// One 8×8-pixel tile of an object's list (ray-cast-tiles.comp) per instance, as two triangles: the
// ray-cast fragment shader then runs only where the object can appear.
uniform uint listBase;   // the object's first entry in castTile
uniform vec2 frameSize;  // pixels

layout(std430, binding = 12) readonly buffer CastTiles {
  uint castTile[];  // x | y << 16, in tiles
};

const vec2 kCorners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));

void main() {
  uint tile = castTile[listBase + uint(gl_InstanceID)];
  vec2 pixel = (vec2(tile & 0xFFFFu, tile >> 16) + kCorners[gl_VertexID]) * 8.0;
  gl_Position = vec4(min(pixel, frameSize) / frameSize * 2.0 - 1.0, 1.0, 1.0);
}
