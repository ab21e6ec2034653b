// The pixels of one mirror part that no virtual object landed on: a DrawArraysIndirect command
// (count = pixels listed) followed by each pixel packed as x | y << 16.
layout(std430, binding = 8) buffer UncoveredPixels {
  uint drawCount;
  uint drawInstances;
  uint drawFirst;
  uint drawBaseInstance;
  uint uncoveredPixel[];
};
