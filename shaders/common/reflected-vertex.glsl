// One reflected vertex per (mirror, object vertex) slot: written by the search, read by the
// virtual-object pass and, for statistics and benchmarks, by the CPU (passes/ReflectedVertex.h).

const int kReflectionHidden = 1;    // region C: reflected by the inverse rule, still drawn
const int kReflectionUnsolved = 2;  // no mirror texel found: its triangles are dropped
const int kReflectionColdStart = 4; // searched from the pyramid, not from last frame's texel
const int kReflectionEnlarged = 8;  // ray hierarchy: in no cone until Szabo's enlargement
const int kReflectionInNoCone = 16; // ray hierarchy: in no cone even enlarged (hidden or unreflected)

struct ReflectedVertex {
  vec4 virtualPosition;   // world space; w = 1 when solved
  vec4 reflectionPoint;   // world space R
  vec4 reflectionNormal;  // unit N at R
  ivec4 state;            // xy: level-0 texel (next frame's seed), z: search steps, w: flags
};
