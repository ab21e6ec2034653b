// The scene's environment for a shader: what a ray that meets nothing sees in `direction` (world space).
// Uniforms set by passes::setEnvironment; the image, when there is one, is bound on its own unit.
#include "common/environment-radiance.glsl"

uniform int environmentKind;     // ENVIRONMENT_COLOUR, ENVIRONMENT_SKY or ENVIRONMENT_IMAGE
uniform vec3 environmentColour;  // the scene's background, linear RGB
layout(binding = ENVIRONMENT_TEXTURE_UNIT) uniform sampler2D environmentImage;  // sRGB texels, linear when sampled

vec3 environmentRadiance(vec3 direction) {
  if (environmentKind == ENVIRONMENT_SKY) return proceduralSky(direction);
  // The finest level, as the reference samples it: the mapping's derivatives jump at the seam.
  if (environmentKind == ENVIRONMENT_IMAGE) return textureLod(environmentImage, equirectangularUv(direction), 0.0).rgb;
  return environmentColour;
}
