// Reflection-point math: the GLSL twin of server/math/Reflection.{h,cpp}; tests compare the two.

// Largest exactly where R with unit normal N reflects `vertex` towards `eye` (N·B = 1). Orders
// points as N·B does, but as −|N × B|² on the front hemisphere: N·B sits within float rounding of 1
// near the solution, where comparing neighbours by it stalls the search on a plateau.
float reflectionObjective(vec3 r, vec3 n, vec3 eye, vec3 vertex) {
  vec3 b = normalize(normalize(eye - r) + normalize(vertex - r));
  float cosine = dot(b, n);
  vec3 sine = cross(n, b);
  return cosine > 0.0 ? -dot(sine, sine) : cosine - 1.0;
}

// The virtual vertex: on the eye's ray through R, a whole path length |O − R| + |R − V| away. Equal
// to V mirrored across the tangent plane when R is exact, but it needs no normal and always projects
// where R does; mirroring magnifies normal errors by about 2|V − R| at grazing reflection points.
vec3 virtualVertex(vec3 eye, vec3 r, vec3 vertex) {
  vec3 ray = r - eye;
  float toMirror = length(ray);
  return eye + (toMirror + length(vertex - r)) / toMirror * ray;
}

// V mirrored across the plane through R with unit normal N: where a vertex hidden behind the
// mirror's silhouette (region C) is placed, just outside the silhouette.
vec3 mirrorAcrossPlane(vec3 r, vec3 n, vec3 vertex) {
  return vertex - 2.0 * dot(vertex - r, n) * n;
}
