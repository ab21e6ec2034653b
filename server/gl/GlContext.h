#pragma once
// A current GL ≥ 4.3 core context with its function table, chosen among the platforms at run time.
#include <memory>
#include <optional>
#include <string>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/GlPlatform.h"

namespace specula::gl {

enum class PlatformChoice { Auto, EglDevice, EglSurfaceless, OsMesa };

// Parses the --gl value: auto | egl-device | egl-surfaceless | osmesa.
std::optional<PlatformChoice> parsePlatformChoice(std::string_view text);

struct GlInfo {
  std::string platform;  // "egl-device", "egl-surfaceless" or "osmesa"
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
};

// Owns one context. Not thread-safe: use it from one thread at a time, after makeCurrent().
class GlContext {
 public:
  // Auto tries egl-device, egl-surfaceless, osmesa in that order; the error names every attempt
  // and the packages that would fix it.
  static Result<std::unique_ptr<GlContext>> create(PlatformChoice choice);

  const GlApi& api() const { return api_; }
  // The function table itself, for wrapping entry points: everything made from this context calls
  // through it (tests count the calls that wait for the GPU).
  GlApi& apiToInstrument() { return api_; }
  const GlInfo& info() const { return info_; }
  Status makeCurrent() { return platform_->makeCurrent(); }

 private:
  GlContext(std::unique_ptr<GlPlatform> platform) : platform_(std::move(platform)) {}
  Status initialize();

  std::unique_ptr<GlPlatform> platform_;
  GlApi api_;
  GlInfo info_;
};

}  // namespace specula::gl
