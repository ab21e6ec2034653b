// A bicubic Bézier patch (math::BezierPatch): 16 control points row-major, u along a row. The GLSL
// twin of BezierPatch::sample for the patch tessellation and the exact mirror G-buffer (checked
// against the ray tracer's patches in tests/gl/ParametricMirrorTest.cpp).

// The storage binding: passes::GpuMeshes::kPatchPointsBinding unless the including shader, whose own
// buffers use that one, defines another first.
#ifndef PATCH_POINTS_BINDING
#define PATCH_POINTS_BINDING 1
#endif
layout(std430, binding = PATCH_POINTS_BINDING) readonly buffer PatchPoints {
  vec4 patchPoints[];  // 16 per patch, object space
};

// Position and partial derivatives at (u, v) of the patch whose control points start at `first`.
void bezierPatchSample(int first, vec2 uv, out vec3 position, out vec3 du, out vec3 dv) {
  vec2 s = 1.0 - uv;
  vec4 bu = vec4(s.x * s.x * s.x, 3.0 * uv.x * s.x * s.x, 3.0 * uv.x * uv.x * s.x, uv.x * uv.x * uv.x);
  vec4 bv = vec4(s.y * s.y * s.y, 3.0 * uv.y * s.y * s.y, 3.0 * uv.y * uv.y * s.y, uv.y * uv.y * uv.y);
  vec4 dbu = vec4(-3.0 * s.x * s.x, 3.0 * s.x * s.x - 6.0 * uv.x * s.x, 6.0 * uv.x * s.x - 3.0 * uv.x * uv.x, 3.0 * uv.x * uv.x);
  vec4 dbv = vec4(-3.0 * s.y * s.y, 3.0 * s.y * s.y - 6.0 * uv.y * s.y, 6.0 * uv.y * s.y - 3.0 * uv.y * uv.y, 3.0 * uv.y * uv.y);
  position = vec3(0.0);
  du = vec3(0.0);
  dv = vec3(0.0);
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) {
      vec3 p = patchPoints[first + 4 * row + column].xyz;
      position += bu[column] * bv[row] * p;
      du += dbu[column] * bv[row] * p;
      dv += bu[column] * dbv[row] * p;
    }
}
