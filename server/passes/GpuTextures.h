#pragma once
// The scene's textures on the GPU, uploaded once with the mip levels scene::Texture holds (built in
// linear light on the CPU, so the reference's sampler filters the same texels), as sRGB8 so the
// sampler decodes to linear before filtering.
#include <cstdint>
#include <optional>
#include <vector>

#include "gl/GlApi.h"
#include "gl/GlObject.h"
#include "common/environment-radiance.glsl"
#include "scene/Scene.h"

namespace specula::passes {

class GpuTextures {
 public:
  // The texture unit shading.glsl's materialTexture samples; no pass binds anything else there.
  static constexpr GLuint kMaterialTextureUnit = 7;

  GpuTextures(const gl::GlApi& gl, const std::vector<scene::Texture>& textures);

  // Binds texture `index` (a 1×1 white one when nullopt, so the sampler is always complete) on
  // kMaterialTextureUnit; leaves GL_TEXTURE0 active.
  void bind(std::optional<std::uint32_t> index) const { bindOn(kMaterialTextureUnit, index); }
  // The same on ENVIRONMENT_TEXTURE_UNIT, where shaders/common/environment.glsl samples the environment image.
  void bindEnvironment(std::optional<std::uint32_t> index) const { bindOn(ENVIRONMENT_TEXTURE_UNIT, index); }
  std::size_t size() const { return textures_.size(); }

 private:
  void bindOn(GLuint unit, std::optional<std::uint32_t> index) const;

  const gl::GlApi* gl_;
  std::vector<gl::GlTexture> textures_;
  gl::GlTexture white_;
};

}  // namespace specula::passes
