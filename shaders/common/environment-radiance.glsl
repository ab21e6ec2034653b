// What a ray that meets nothing sees, one definition for the GPU passes (shaders/common/environment.glsl)
// and the reference ray tracer (reference/EnvironmentRadiance): the procedural sky, the equirectangular
// mapping of an environment image, and the environment kinds. Directions are world space, +y up.
#ifdef __cplusplus
#pragma once
#include <glm/glm.hpp>
namespace specula::environment {
using glm::acos, glm::atan, glm::clamp, glm::dot, glm::exp, glm::max, glm::mix, glm::normalize, glm::pow;
using glm::vec2, glm::vec3;
#define ENVIRONMENT_FUNCTION inline
#else
#define ENVIRONMENT_FUNCTION
#endif

#define ENVIRONMENT_COLOUR 0  // a uniform colour: the scene's background
#define ENVIRONMENT_SKY 1     // proceduralSky
#define ENVIRONMENT_IMAGE 2   // an equirectangular image
#define ENVIRONMENT_TEXTURE_UNIT 5

// Longitude and latitude as texture coordinates: u = 0.5 looking down −z, growing towards +x; v = 0 at
// the zenith (the image's top row), 1 at the nadir.
ENVIRONMENT_FUNCTION vec2 equirectangularUv(vec3 direction) {
  vec3 d = normalize(direction);
  return vec2(0.5f + atan(d.x, -d.z) * 0.15915494f, acos(clamp(d.y, -1.0f, 1.0f)) * 0.31830989f);
}

// A clear day: deep blue at the zenith, pale at the horizon, a warm glow around the sun, and ground
// that darkens below the horizon. Continuous everywhere (no horizon line, no sun disc), so a
// reflection's error shows as an error and not as a hard edge landing a pixel off.
ENVIRONMENT_FUNCTION vec3 proceduralSky(vec3 direction) {
  vec3 d = normalize(direction);
  const vec3 zenith = vec3(0.08f, 0.20f, 0.52f);
  const vec3 horizon = vec3(0.62f, 0.72f, 0.84f);
  const vec3 ground = vec3(0.16f, 0.14f, 0.12f);
  const vec3 sunDirection = vec3(0.42426407f, 0.56568542f, -0.70710678f);  // normalize(0.6, 0.8, −1)
  const vec3 sunGlow = vec3(1.0f, 0.78f, 0.52f);
  vec3 colour =
      d.y >= 0.0f ? mix(horizon, zenith, 1.0f - exp(-3.0f * d.y)) : mix(horizon, ground, 1.0f - exp(8.0f * d.y));
  float toSun = max(dot(d, sunDirection), 0.0f);
  return colour + sunGlow * (0.6f * pow(toSun, 48.0f) + 0.15f * pow(toSun, 6.0f));
}

#ifdef __cplusplus
}  // namespace specula::environment
#endif
