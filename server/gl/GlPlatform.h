#pragma once
// A headless GL context provider: EGL on a GPU device, EGL surfaceless (Mesa llvmpipe) or OSMesa.
// A platform owns exactly one context, current on the thread that created it.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"

namespace specula::gl {

enum class PlatformKind { EglDevice, EglSurfaceless, OsMesa };

// The --gl names: "egl-device", "egl-surfaceless", "osmesa".
std::string_view platformName(PlatformKind kind);

class GlPlatform {
 public:
  virtual ~GlPlatform() = default;
  virtual PlatformKind kind() const = 0;
  // Address of a GL entry point in this context, or nullptr.
  virtual void* procAddress(const char* name) const = 0;
  // Makes the context current on the calling thread (after a move to another thread).
  virtual Status makeCurrent() = 0;
};

// SPECULA_GL_DEBUG=1 asks for a debug context whose driver messages (errors, performance warnings
// such as shader recompiles or stalls) are printed to stderr: how to see what a driver does slowly.
bool glDebugOutputRequested();

// Each creates a GL ≥ 4.3 core context or says why not (naming the library or extension missing).
Result<std::unique_ptr<GlPlatform>> createEglDevicePlatform();
Result<std::unique_ptr<GlPlatform>> createEglSurfacelessPlatform();
Result<std::unique_ptr<GlPlatform>> createOsMesaPlatform();

}  // namespace specula::gl
