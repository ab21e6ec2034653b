#pragma once
// The platforms every GL test runs on: both must work on a machine without a GPU.
#include <gtest/gtest.h>

#include "gl/GlContext.h"

namespace specula::testing {

inline const auto kSoftwarePlatforms =
    ::testing::Values(gl::PlatformChoice::EglSurfaceless, gl::PlatformChoice::OsMesa);

inline std::string platformTestName(const ::testing::TestParamInfo<gl::PlatformChoice>& info) {
  return info.param == gl::PlatformChoice::OsMesa ? "OsMesa" : "EglSurfaceless";
}

}  // namespace specula::testing
