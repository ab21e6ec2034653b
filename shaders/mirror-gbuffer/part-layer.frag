#version 430 core
// One part's G-buffer layer from its parametric mirror drawn whole into scratch textures
// (mirror-gbuffer-patch.frag, each texel's part + 1 in the normal's w): every texel copied, only the
// part's own marked (w = 1), so the other parts still hide what lies behind them. Tessellating and
// evaluating the patches once per part instead cost more than these copies.

uniform sampler2D drawnPosition;
uniform sampler2D drawnNormal;
uniform sampler2D drawnSurface;
uniform int part;  // the part this layer holds

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outSurface;  // (u, v, patch, 1) on the part's texels

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 normal = texelFetch(drawnNormal, texel, 0);
  bool inPart = normal.w == float(part + 1);  // 0 where the mirror is absent
  outPosition = vec4(texelFetch(drawnPosition, texel, 0).xyz, inPart ? 1.0 : 0.0);
  outNormal = vec4(normal.xyz, 0.0);
  outSurface = inPart ? texelFetch(drawnSurface, texel, 0) : vec4(0.0);
}
