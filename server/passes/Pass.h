#pragma once
// One step of a frame. A pass owns its GL program; which passes run, in which order and for which
// mirrors and objects is decided before them, as plain data (passes/FramePlan).
#include <string_view>

#include "passes/FrameContext.h"

namespace specula::passes {

class Pass {
 public:
  virtual ~Pass() = default;
  virtual std::string_view name() const = 0;  // same as its shaders/ folder
  virtual void execute(const FrameContext& frame) = 0;
};

}  // namespace specula::passes
