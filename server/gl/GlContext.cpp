#include "gl/GlContext.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace specula::gl {

namespace {

struct PlatformOption {
  PlatformKind kind;
  Result<std::unique_ptr<GlPlatform>> (*create)();
};
constexpr std::array<PlatformOption, 3> kPlatformsInAutoOrder{{
    {PlatformKind::EglDevice, &createEglDevicePlatform},
    {PlatformKind::EglSurfaceless, &createEglSurfacelessPlatform},
    {PlatformKind::OsMesa, &createOsMesaPlatform},
}};

constexpr const char* kInstallHint =
    "install Mesa's software GL (apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6, "
    "or run docker/install-deps.sh --runtime) or a GPU driver with EGL (e.g. NVIDIA's)";

std::string glString(const GlApi& gl, GLenum name) {
  const GLubyte* text = gl.GetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

// Prints each driver message once per (source, type, id), then stays quiet: a per-draw warning
// would otherwise flood the log every frame.
void APIENTRY printDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                const void*) {
  static constexpr std::size_t kRemembered = 256;
  static std::array<std::array<GLuint, 3>, kRemembered> seen{};
  static std::size_t seenCount = 0;
  const std::array<GLuint, 3> key{source, type, id};
  for (std::size_t i = 0; i < seenCount; ++i)
    if (seen[i] == key) return;
  if (seenCount < kRemembered) seen[seenCount++] = key;
  std::fprintf(stderr, "GL debug (source 0x%X, type 0x%X, id %u, severity 0x%X): %s\n", source, type, id, severity,
               message);
}

}  // namespace

bool glDebugOutputRequested() {
  const char* value = std::getenv("SPECULA_GL_DEBUG");
  return value && std::strcmp(value, "") != 0 && std::strcmp(value, "0") != 0;
}

std::string_view platformName(PlatformKind kind) {
  switch (kind) {
    case PlatformKind::EglDevice: return "egl-device";
    case PlatformKind::EglSurfaceless: return "egl-surfaceless";
    case PlatformKind::OsMesa: return "osmesa";
  }
  return "?";
}

std::optional<PlatformChoice> parsePlatformChoice(std::string_view text) {
  if (text == "auto") return PlatformChoice::Auto;
  if (text == "egl-device") return PlatformChoice::EglDevice;
  if (text == "egl-surfaceless") return PlatformChoice::EglSurfaceless;
  if (text == "osmesa") return PlatformChoice::OsMesa;
  return std::nullopt;
}

Result<std::unique_ptr<GlContext>> GlContext::create(PlatformChoice choice) {
  std::string attempts;
  for (const PlatformOption& option : kPlatformsInAutoOrder) {
    const bool wanted = choice == PlatformChoice::Auto ||
                        (choice == PlatformChoice::EglDevice && option.kind == PlatformKind::EglDevice) ||
                        (choice == PlatformChoice::EglSurfaceless && option.kind == PlatformKind::EglSurfaceless) ||
                        (choice == PlatformChoice::OsMesa && option.kind == PlatformKind::OsMesa);
    if (!wanted) continue;
    auto platform = option.create();
    std::string problem;
    if (platform) {
      std::unique_ptr<GlContext> context(new GlContext(std::move(platform.value())));
      Status status = context->initialize();
      if (status) return context;
      problem = status.error();
    } else {
      problem = platform.error();
    }
    attempts += (attempts.empty() ? "" : "; ") + std::string(platformName(option.kind)) + ": " + problem;
  }
  return Error{"no headless GL platform worked (" + attempts + "); " + kInstallHint};
}

Status GlContext::initialize() {
  const std::string missing = api_.load(
      [](const char* name, void* user) { return static_cast<GlPlatform*>(user)->procAddress(name); }, platform_.get());
  if (!missing.empty()) return Error{"GL entry points missing: " + missing};
  info_ = {std::string(platformName(platform_->kind())), glString(api_, GL_RENDERER), glString(api_, GL_VERSION),
           glString(api_, GL_VENDOR)};
  GLint major = 0, minor = 0;
  api_.GetIntegerv(GL_MAJOR_VERSION, &major);
  api_.GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43) return Error{"GL " + info_.version + " is older than the 4.3 core profile needed"};
  if (glDebugOutputRequested()) {
    const auto callback =
        reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(platform_->procAddress("glDebugMessageCallback"));
    if (!callback) return Error{"SPECULA_GL_DEBUG is set but the driver lacks glDebugMessageCallback"};
    api_.Enable(GL_DEBUG_OUTPUT);
    api_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // messages arrive on the calling thread, next to their call
    callback(printDebugMessage, nullptr);
    GLint flags = 0;
    api_.GetIntegerv(GL_CONTEXT_FLAGS, &flags);
    std::fprintf(stderr, "GL debug output on (SPECULA_GL_DEBUG)%s\n",
                 (flags & GL_CONTEXT_FLAG_DEBUG_BIT)
                     ? ""
                     : ", but the platform gave no debug context: the driver may stay silent");
  }
  return {};
}

}  // namespace specula::gl
