// Reflection-point math: the GLSL twin of server/math/Reflection.{h,cpp}; tests compare the two.

// N·B: 1 exactly where R with unit normal N reflects `vertex` towards `eye`; the search maximises it.
float reflectionObjective(vec3 r, vec3 n, vec3 eye, vec3 vertex) {
  return dot(normalize(normalize(eye - r) + normalize(vertex - r)), n);
}

// V mirrored across the tangent plane at R: the virtual vertex, |V − R| behind the mirror.
vec3 virtualVertex(vec3 r, vec3 n, vec3 vertex) {
  return vertex - 2.0 * dot(vertex - r, n) * n;
}
