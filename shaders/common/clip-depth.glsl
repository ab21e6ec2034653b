// Window depth of a world point, for fragments that place themselves exactly.
float clipDepth(mat4 worldToClip, vec3 world) {
  vec4 clip = worldToClip * vec4(world, 1.0);
  return clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
}
