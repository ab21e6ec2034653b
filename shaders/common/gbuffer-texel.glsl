// The G-buffer texel under a frame pixel: the G-buffer covers the frame widened by a margin, at its
// own resolution. Uniforms set by passes::setGBufferPixelMapping.
uniform vec2 marginPixels;     // G-buffer border, frame pixels per side
uniform float texelsPerPixel;  // G-buffer resolution

ivec2 gbufferTexelAt(vec2 fragCoord) { return ivec2((fragCoord + marginPixels) * texelsPerPixel); }
