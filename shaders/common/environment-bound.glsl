// Whether a mirror pixel's environment-map lookup lands within the error budget of its true
// reflection (passes::environmentMapReach): a direction error moves the reflection by the reach
// over the pixel's distance and incidence cosine, which grows without bound towards a silhouette.
// The environment-map pass draws the pixels where it holds; the virtual-objects pass ray-casts the
// others. A reach of 0 (the environment-map method itself) holds everywhere.
uniform float environmentReach;  // pixels at one metre and normal incidence
uniform float errorBudget;       // pixels

bool environmentLookupHolds(vec3 surface, vec3 normal, vec3 eye) {
  if (environmentReach == 0.0) return true;
  vec3 toSurface = surface - eye;
  float distance = length(toSurface);
  float cosine = -dot(toSurface, normal) / distance;
  return cosine > 0.0 && environmentReach <= errorBudget * cosine * distance;
}
