#pragma once
// Move-only owners of GL object names; the name is deleted with the owner. The context must be
// current on the thread that creates, uses and destroys them.
#include <atomic>
#include <cstdint>
#include <utility>

#include "gl/GlApi.h"

namespace specula::gl {

enum class GlObjectType { Buffer, Texture, Framebuffer, VertexArray, Query };

// GL object names created so far, of every type, on every thread: tests check that frames of one
// size create none.
inline std::atomic<std::uint64_t> glObjectsCreated{0};
// GL object names owned now (created and not yet deleted), of every type, on every thread: the
// service's specula_gl_objects gauge, which `specula bench soak` watches for leaks.
inline std::atomic<std::int64_t> glObjectsLive{0};

template <GlObjectType Type>
class GlObject {
 public:
  explicit GlObject(const GlApi& gl) : gl_(&gl) {
    glObjectsCreated.fetch_add(1, std::memory_order_relaxed);
    if constexpr (Type == GlObjectType::Buffer) gl.GenBuffers(1, &id_);
    if constexpr (Type == GlObjectType::Texture) gl.GenTextures(1, &id_);
    if constexpr (Type == GlObjectType::Framebuffer) gl.GenFramebuffers(1, &id_);
    if constexpr (Type == GlObjectType::VertexArray) gl.GenVertexArrays(1, &id_);
    if constexpr (Type == GlObjectType::Query) gl.GenQueries(1, &id_);
    if (id_ != 0) glObjectsLive.fetch_add(1, std::memory_order_relaxed);
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
    glObjectsLive.fetch_sub(1, std::memory_order_relaxed);
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

// A buffer that only grows: storage for the largest size asked for so far, so that frames of one
// size allocate once. Contents are undefined after a reserve that grows it.
class GlGrowingBuffer {
 public:
  explicit GlGrowingBuffer(const GlApi& gl) : buffer_(gl) {}
  GLuint id() const { return buffer_.id(); }
  void reserve(const GlApi& gl, GLsizeiptr bytes) {
    if (bytes <= bytes_) return;
    gl.BindBuffer(GL_COPY_WRITE_BUFFER, buffer_.id());
    gl.BufferData(GL_COPY_WRITE_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
    bytes_ = bytes;
  }

 private:
  GlBuffer buffer_;
  GLsizeiptr bytes_ = 0;
};

}  // namespace specula::gl
