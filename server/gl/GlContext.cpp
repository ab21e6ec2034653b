#include "gl/GlContext.h"

#include <array>

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

}  // namespace

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
  return {};
}

}  // namespace specula::gl
