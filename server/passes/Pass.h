#pragma once
// One step of a frame. A pass owns its GL program; which passes run, in which order and for which
// mirrors and objects is decided before them, as plain data (passes/FramePlan).
#include <string_view>

#include "passes/FrameContext.h"
#include "passes/FrameGraph.h"

namespace specula::passes {

class Pass {
 public:
  virtual ~Pass() = default;
  virtual PassId id() const = 0;
  std::string_view name() const { return passName(id()); }  // same as its shaders/ folder
  virtual void execute(const FrameContext& frame) = 0;
};

}  // namespace specula::passes
