#include "passes/GpuTextures.h"

namespace specula::passes {

namespace {

GLint glWrap(scene::TextureWrap wrap) {
  switch (wrap) {
    case scene::TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case scene::TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case scene::TextureWrap::Repeat: break;
  }
  return GL_REPEAT;
}

void upload(const gl::GlApi& gl, const gl::GlTexture& target, const scene::Texture& texture) {
  gl.BindTexture(GL_TEXTURE_2D, target.id());
  const scene::TextureLevel& base = texture.levels.front();
  gl.TexStorage2D(GL_TEXTURE_2D, static_cast<GLsizei>(texture.levels.size()), GL_SRGB8_ALPHA8, base.width, base.height);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::size_t i = 0; i < texture.levels.size(); ++i) {
    const scene::TextureLevel& level = texture.levels[i];
    gl.TexSubImage2D(GL_TEXTURE_2D, static_cast<GLint>(i), 0, 0, level.width, level.height, GL_RGBA, GL_UNSIGNED_BYTE,
                     level.rgba.data());
  }
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(texture.wrapU));
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(texture.wrapV));
}

}  // namespace

GpuTextures::GpuTextures(const gl::GlApi& gl, const std::vector<scene::Texture>& textures) : gl_(&gl), white_(gl) {
  textures_.reserve(textures.size());
  for (const scene::Texture& texture : textures) upload(gl, textures_.emplace_back(gl), texture);
  upload(gl, white_, scene::textureFromPixels("white", 1, 1, {255, 255, 255, 255}));
  gl.BindTexture(GL_TEXTURE_2D, 0);
}

void GpuTextures::bindOn(GLuint unit, std::optional<std::uint32_t> index) const {
  gl_->ActiveTexture(GL_TEXTURE0 + unit);
  gl_->BindTexture(GL_TEXTURE_2D, index ? textures_.at(*index).id() : white_.id());
  gl_->ActiveTexture(GL_TEXTURE0);
}

}  // namespace specula::passes
