#include "gl/GpuReadback.h"

#include <algorithm>

namespace specula::gl {

namespace {
constexpr std::size_t kAlignment = 16;  // each copy's place in the staging buffer
constexpr GLbitfield kMapping = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
constexpr GLuint64 kGiveUpNanoseconds = 10'000'000'000;  // a GPU that has not finished a frame in 10 s is lost
}  // namespace

GpuReadback::~GpuReadback() {
  releaseSync();
  if (mapped_) {
    gl_->BindBuffer(GL_COPY_READ_BUFFER, staging_.id());
    gl_->UnmapBuffer(GL_COPY_READ_BUFFER);
    gl_->BindBuffer(GL_COPY_READ_BUFFER, 0);
  }
}

void GpuReadback::releaseSync() {
  if (sync_) gl_->DeleteSync(sync_);
  sync_ = nullptr;
}

void GpuReadback::begin() {
  releaseSync();
  copies_.clear();
}

std::size_t GpuReadback::copy(GLuint buffer, std::size_t bytes, std::size_t offset) {
  const std::size_t staged =
      copies_.empty() ? 0 : (copies_.back().staged + copies_.back().bytes + kAlignment - 1) / kAlignment * kAlignment;
  copies_.push_back({buffer, offset, bytes, staged});
  return copies_.size() - 1;
}

void GpuReadback::fence() {
  const GlApi& gl = *gl_;
  const std::size_t needed = copies_.empty() ? 0 : copies_.back().staged + copies_.back().bytes;
  if (needed > capacity_) {
    // Immutable storage cannot grow: a new buffer, mapped for good.
    if (mapped_) {
      gl.BindBuffer(GL_COPY_READ_BUFFER, staging_.id());
      gl.UnmapBuffer(GL_COPY_READ_BUFFER);
    }
    capacity_ = std::max(needed, 2 * capacity_);
    staging_ = GlBuffer(gl);
    gl.BindBuffer(GL_COPY_READ_BUFFER, staging_.id());
    gl.BufferStorage(GL_COPY_READ_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, kMapping);
    mapped_ = static_cast<const unsigned char*>(
        gl.MapBufferRange(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(capacity_), kMapping));
    gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
  }
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // shader writes before the copies read them
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, staging_.id());
  for (const Copy& copy : copies_) {
    gl.BindBuffer(GL_COPY_READ_BUFFER, copy.buffer);
    gl.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(copy.offset),
                         static_cast<GLintptr>(copy.staged), static_cast<GLsizeiptr>(copy.bytes));
  }
  gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
  gl.BindBuffer(GL_COPY_WRITE_BUFFER, 0);
  releaseSync();
  sync_ = gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool GpuReadback::wait() {
  if (!sync_) return copies_.empty();
  GLenum state = gl_->ClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
  if (state == GL_TIMEOUT_EXPIRED) state = gl_->ClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, kGiveUpNanoseconds);
  return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
}

}  // namespace specula::gl
