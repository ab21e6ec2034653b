// Ofek & Rappoport's (1998) explosion map, §4: the directions of a mirror part's reflected eye rays,
// seen from a centre C through a sphere about it, laid out like a circular environment map. Shared
// by the map's build (explosion-map/) and its look-ups (search/explosion-map-search.glsl).
uniform vec3 explosionCentre;  // C: the part's bounding-sphere centre, world
uniform mat3 explosionAxes;    // columns x, y, z of the map's frame; z points from C to the eye
uniform vec2 explosionRadii;   // the near sphere's radius (bounds the part), the far one's (bounds the scene)

// The map circle (every direction) has radius 1 in map units; extension polygons reach 1.2 (the
// paper's 0.6 s); the texture spans ±kExplosionExtent.
const float kExplosionExtent = 1.25;
const float kExtensionRadius = 1.2;

// MapCoords: a unit direction to map units. The direction towards the eye maps to the centre, the
// one straight away from it to the rim.
vec2 explosionMapCoords(vec3 direction) {
  vec3 local = transpose(explosionAxes) * direction;
  return local.xy / sqrt(max(2.0 * (local.z + 1.0), 1e-12));
}

// The normal the map uses at a mirror vertex: a back-facing one is turned square to the eye's ray
// (the paper's fix for profile triangles), so its reflected ray grazes on along that ray.
vec3 explosionNormal(vec3 position, vec3 normal, vec3 eye) {
  vec3 view = normalize(position - eye);
  if (dot(normal, view) <= 0.0) return normal;
  vec3 square = normal - dot(normal, view) * view;
  return dot(square, square) > 1e-12 ? normalize(square) : normal;
}

// Where the reflected eye ray at a mirror vertex leaves the sphere of `radius` about C, as map coordinates.
vec2 explosionVertexCoords(vec3 position, vec3 normal, vec3 eye, float radius) {
  vec3 ray = reflect(normalize(position - eye), normal);
  vec3 offset = position - explosionCentre;
  float b = dot(offset, ray), c = dot(offset, offset) - radius * radius;
  float t = -b + sqrt(max(b * b - c, 0.0));  // from inside the sphere: the far root
  return explosionMapCoords(normalize(offset + t * ray));
}
