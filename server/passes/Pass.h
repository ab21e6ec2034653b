#pragma once
// One step of a frame. A pass owns its GL program and declares the frame resources it reads and
// writes, so the frame graph (plain data) can be planned and tested without GL.
#include <span>
#include <string_view>

#include "passes/FrameContext.h"

namespace specula::passes {

class Pass {
 public:
  virtual ~Pass() = default;
  virtual std::string_view name() const = 0;  // same as its shaders/ folder
  virtual std::span<const std::string_view> reads() const = 0;
  virtual std::span<const std::string_view> writes() const = 0;
  virtual void execute(const FrameContext& frame) = 0;
};

}  // namespace specula::passes
