#pragma once
// Move-only owners of GL object names; the name is deleted with the owner. The context must be
// current on the thread that creates, uses and destroys them.
#include <utility>

#include "gl/GlApi.h"

namespace specula::gl {

enum class GlObjectType { Buffer, Texture, Framebuffer, VertexArray, Query };

template <GlObjectType Type>
class GlObject {
 public:
  explicit GlObject(const GlApi& gl) : gl_(&gl) {
    if constexpr (Type == GlObjectType::Buffer) gl.GenBuffers(1, &id_);
    if constexpr (Type == GlObjectType::Texture) gl.GenTextures(1, &id_);
    if constexpr (Type == GlObjectType::Framebuffer) gl.GenFramebuffers(1, &id_);
    if constexpr (Type == GlObjectType::VertexArray) gl.GenVertexArrays(1, &id_);
    if constexpr (Type == GlObjectType::Query) gl.GenQueries(1, &id_);
  }
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept : gl_(other.gl_), id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      gl_ = other.gl_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }

 private:
  void reset() {
    if (id_ == 0) return;
    if constexpr (Type == GlObjectType::Buffer) gl_->DeleteBuffers(1, &id_);
    if constexpr (Type == GlObjectType::Texture) gl_->DeleteTextures(1, &id_);
    if constexpr (Type == GlObjectType::Framebuffer) gl_->DeleteFramebuffers(1, &id_);
    if constexpr (Type == GlObjectType::VertexArray) gl_->DeleteVertexArrays(1, &id_);
    if constexpr (Type == GlObjectType::Query) gl_->DeleteQueries(1, &id_);
    id_ = 0;
  }

  const GlApi* gl_;
  GLuint id_ = 0;
};

using GlBuffer = GlObject<GlObjectType::Buffer>;
using GlTexture = GlObject<GlObjectType::Texture>;
using GlFramebuffer = GlObject<GlObjectType::Framebuffer>;
using GlVertexArray = GlObject<GlObjectType::VertexArray>;
using GlQuery = GlObject<GlObjectType::Query>;

}  // namespace specula::gl
