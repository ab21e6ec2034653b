#pragma once
// Small GPU buffers read back without stalling: copies queued into a persistently mapped buffer,
// a fence after them, and the bytes read once the fence has passed. A frame queues its statistics
// before its final image is read; that read waits for the frame anyway, so the fence has passed by
// then and the statistics cost no wait of their own.
#include <cstddef>
#include <cstring>
#include <vector>

#include "gl/GlApi.h"
#include "gl/GlObject.h"

namespace specula::gl {

class GpuReadback {
 public:
  explicit GpuReadback(const GlApi& gl) : gl_(&gl), staging_(gl) {}
  ~GpuReadback();
  GpuReadback(const GpuReadback&) = delete;
  GpuReadback& operator=(const GpuReadback&) = delete;

  // Forgets the last set of copies and starts a new one.
  void begin();
  // Queues a copy of `bytes` at `offset` of `buffer` (written by shaders before this call); the
  // handle names it for read().
  std::size_t copy(GLuint buffer, std::size_t bytes, std::size_t offset = 0);
  // Issues the queued copies and a fence after them.
  void fence();
  // Makes the copies readable: at once when the fence has passed (what a frame expects after its
  // image was read), else by waiting for it. Returns false if the GPU never got there.
  bool wait();
  // The copy `handle`'s bytes as `count` values of T (after wait()).
  template <class T>
  std::vector<T> read(std::size_t handle, std::size_t count) const {
    std::vector<T> values(count);
    if (count > 0) std::memcpy(values.data(), mapped_ + copies_[handle].staged, count * sizeof(T));
    return values;
  }
  template <class T>
  T read(std::size_t handle) const {
    return read<T>(handle, 1)[0];
  }

 private:
  struct Copy {
    GLuint buffer;
    std::size_t offset, bytes, staged;
  };
  void releaseSync();

  const GlApi* gl_;
  GlBuffer staging_;  // immutable storage, mapped for reading for its whole life
  std::size_t capacity_ = 0;
  const unsigned char* mapped_ = nullptr;
  std::vector<Copy> copies_;
  GLsync sync_ = nullptr;
};

}  // namespace specula::gl
