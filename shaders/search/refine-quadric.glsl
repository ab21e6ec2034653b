// Refinement on the exact surface of an analytic mirror (common/quadric.glsl) instead of the G-buffer.
#include "common/quadric.glsl"
#include "search/refine.glsl"

const float kContactHeight = 1e-3;  // unit-sphere radii: closer vertices reflect from their foot point
const float kStalledResidual = 0.1;  // normal and bisector still this far apart (sine): the refinement is lost

vec3 tangentialBisectorOnQuadric(vec3 unitPoint) {
  vec3 p, n;
  quadricSurface(unitPoint, p, n);
  return tangentialBisector(p, n);
}

// Gauss–Newton on the exact surface of an analytic mirror, from the climb's texel, in coordinates
// of the unit sphere's tangent plane at the current point: unlike G-buffer coordinates they stay
// well conditioned up to the silhouette, where one texel spans a wide arc of the surface and the
// bilinear surface strays from the true one.
// Returns false when it is lost: far from any reflection point (a start on the wrong side).
bool refineOnQuadric(vec3 start, out vec3 position, out vec3 normal) {
  vec3 unitVertex = toUnitSpace(vertexWorld);
  // A vertex touching the mirror (or on or in it) reflects from within its height of its foot
  // point, where the residual turns too fast for float derivatives: take the foot point.
  if (length(unitVertex) - 1.0 < kContactHeight) {
    quadricSurface(normalize(unitVertex), position, normal);
    return true;
  }
  vec3 unitEye = toUnitSpace(eyePosition);
  // Central-difference step, radians on the unit sphere: below the vertex's height above the
  // surface, over which the residual turns when the vertex nearly touches the mirror.
  float h = clamp(0.25 * (length(toUnitSpace(vertexWorld)) - 1.0), 1e-5, 1e-3);
  vec3 u = normalize(toUnitSpace(start));
  for (int iteration = 0; iteration < 24; ++iteration) {  // a texel of a small mirror spans a wide arc
    vec3 t1 = normalize(cross(u, abs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(u, t1);
    vec3 r0 = tangentialBisectorOnQuadric(u);
    vec3 jx = (tangentialBisectorOnQuadric(normalize(u + h * t1)) - tangentialBisectorOnQuadric(normalize(u - h * t1))) / (2.0 * h);
    vec3 jy = (tangentialBisectorOnQuadric(normalize(u + h * t2)) - tangentialBisectorOnQuadric(normalize(u - h * t2))) / (2.0 * h);
    mat2 normalMatrix = mat2(dot(jx, jx), dot(jx, jy), dot(jx, jy), dot(jy, jy));
    if (abs(determinant(normalMatrix)) < 1e-30) break;
    vec2 step = -inverse(normalMatrix) * vec2(dot(jx, r0), dot(jy, r0));
    if (length(step) > 0.25) step = 0.25 * normalize(step);
    // Backtracking: halve the step until it stays visible and lowers the residual, which turns
    // sharply when the vertex nearly touches the mirror and full steps would overshoot. Steps under
    // 0.03 rad are trusted: near grazing points the residual does not fall monotonically along them,
    // and testing them stopped convergence early.
    vec3 next = normalize(u + step.x * t1 + step.y * t2);
    int halving = 0;
    for (; halving < 12; ++halving) {
      if (facesEye(next, unitEye)) {
        vec3 r1 = tangentialBisectorOnQuadric(next);
        if (dot(r1, r1) < dot(r0, r0) || length(step) < 0.03) break;
      }
      step *= 0.5;
      next = normalize(u + step.x * t1 + step.y * t2);
    }
    if (halving == 12) break;
    u = next;
    if (length(step) < 1e-6) break;  // converged to float precision
  }
  quadricSurface(u, position, normal);
  return length(tangentialBisectorOnQuadric(u)) < kStalledResidual;
}
