#pragma once
#include <memory>
#include <string>

#include "base/CommandLine.h"
#include "base/Result.h"
#include "gl/GlContext.h"

namespace specula::app {

// The --gl option, the same for every command that renders with GL.
inline OptionSpec glOption() { return {"gl", "BACKEND", "auto | egl-device | egl-surfaceless | osmesa", "auto"}; }

// Reads --gl, or says what it accepts.
Result<gl::PlatformChoice> parseGlOption(const std::string& backend);

// Resolves --gl (auto | egl-device | egl-surfaceless | osmesa) to a current context and logs the
// platform, renderer and version chosen on stderr.
Result<std::unique_ptr<gl::GlContext>> openGlContext(const std::string& backend);

}  // namespace specula::app
