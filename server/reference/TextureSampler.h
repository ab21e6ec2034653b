#pragma once
// GL's trilinear filtering (GL_LINEAR_MIPMAP_LINEAR minification, GL_LINEAR magnification, sRGB
// texels decoded before filtering, the texture's wrap modes) restated on the CPU over the same mip
// levels the GPU holds, so the reference ray tracer's texels are the rasterizer's.
#include <glm/glm.hpp>

#include "scene/Texture.h"

namespace specula::reference {

// Linear RGBA of `texture` at `uv` over an isotropic footprint of `uvFootprint` uv units (the
// sampler's ρ is uvFootprint × the larger side; at or below one texel, the finest level).
glm::vec4 sampleTexture(const scene::Texture& texture, glm::vec2 uv, float uvFootprint);

// A pixel's footprint where a traced ray meets a surface, in metres: shading.glsl's pixelFootprint.
float pixelFootprint(float pathLength, float eyeDepthPerLength, float pixelAngle, float cosine);

}  // namespace specula::reference
