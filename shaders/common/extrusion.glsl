// Ofek & Rappoport's (1998, §5) exact reflection points on a mirror declared as a linear extrusion of
// an ellipse (a cylinder): the GLSL twin of server/math/ExtrusionReflection, which says why each step
// holds. Uniforms set by server/passes/QuadricUniforms (setMirrorShape), in world space.
uniform int extrusion;  // 1: this mirror's reflection points are solved here, with no search
uniform vec3 extrusionAxisPoint;
uniform vec3 extrusionU, extrusionV, extrusionDirection;  // orthonormal
uniform vec2 extrusionRadii;                               // semi-axes along U and V

const int kExtrusionBisections = 24;  // the arc is under π wide: 2^-24 π radians, float's own precision

vec2 extrusionProfilePoint(float t) { return extrusionRadii * vec2(cos(t), sin(t)); }
vec2 extrusionProfileNormal(float t) { return normalize(extrusionRadii.yx * vec2(cos(t), sin(t))); }

// The tangential balance of the unit directions to eye and vertex at profile parameter t: positive
// before the reflection point along the arc both see, negative after it.
float extrusionBalance(float t, vec2 eye2, vec2 vertex2) {
  vec2 point = extrusionProfilePoint(t);
  vec2 normal = extrusionProfileNormal(t);
  vec2 tangent = vec2(-normal.y, normal.x);
  return dot(tangent, normalize(eye2 - point)) + dot(tangent, normalize(vertex2 - point));
}

// The reflection point r (unit normal n) of `vertex` seen from `eye`. `hidden`: the vertex is in the
// shadow the eye's tangent planes cast behind the mirror (or inside it); r is then the eye's
// silhouette line on the vertex's side, which its reflection point reaches as it becomes hidden.
// False when the eye is inside the profile and sees none of the outside.
bool extrusionReflection(vec3 eye, vec3 vertex, out vec3 r, out vec3 n, out bool hidden) {
  vec3 eyeOffset = eye - extrusionAxisPoint, vertexOffset = vertex - extrusionAxisPoint;
  vec2 eye2 = vec2(dot(eyeOffset, extrusionU), dot(eyeOffset, extrusionV));
  vec2 vertex2 = vec2(dot(vertexOffset, extrusionU), dot(vertexOffset, extrusionV));
  vec2 eyeUnit = eye2 / extrusionRadii, vertexUnit = vertex2 / extrusionRadii;
  float eyeDistance = length(eyeUnit), vertexDistance = length(vertexUnit);
  r = vec3(0.0);
  n = vec3(0.0);
  hidden = false;
  if (!(eyeDistance > 1.0)) return false;
  float eyeAngle = atan(eyeUnit.y, eyeUnit.x);
  float eyeHalfArc = acos(1.0 / eyeDistance);
  float vertexHalfArc = acos(1.0 / max(vertexDistance, 1.0));
  float offset = atan(vertexUnit.y, vertexUnit.x) - eyeAngle;
  offset -= 6.28318530718 * round(offset / 6.28318530718);
  float low = max(-eyeHalfArc, offset - vertexHalfArc), high = min(eyeHalfArc, offset + vertexHalfArc);
  hidden = low > high || vertexDistance < 1.0;
  float s;
  if (hidden) {
    s = offset < 0.0 ? -eyeHalfArc : eyeHalfArc;
  } else {
    float lowBalance = extrusionBalance(eyeAngle + low, eye2, vertex2);
    float highBalance = extrusionBalance(eyeAngle + high, eye2, vertex2);
    if (!(lowBalance > 0.0) || !(highBalance < 0.0)) {
      s = abs(lowBalance) <= abs(highBalance) ? low : high;  // rounding at an end that is itself the answer
    } else {
      for (int i = 0; i < kExtrusionBisections; ++i) {
        float middle = 0.5 * (low + high);
        if (extrusionBalance(eyeAngle + middle, eye2, vertex2) > 0.0)
          low = middle;
        else
          high = middle;
      }
      s = 0.5 * (low + high);
    }
  }
  float t = eyeAngle + s;
  vec2 point = extrusionProfilePoint(t), normal = extrusionProfileNormal(t);
  float toEye = distance(eye2, point), toVertex = distance(vertex2, point);
  float share = toEye + toVertex > 0.0 ? toEye / (toEye + toVertex) : 0.0;
  float height = mix(dot(eyeOffset, extrusionDirection), dot(vertexOffset, extrusionDirection), share);
  r = extrusionAxisPoint + point.x * extrusionU + point.y * extrusionV + height * extrusionDirection;
  n = normal.x * extrusionU + normal.y * extrusionV;
  return true;
}
