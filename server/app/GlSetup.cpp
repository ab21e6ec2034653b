#include "app/GlSetup.h"

#include <iostream>

namespace specula::app {

Result<gl::PlatformChoice> parseGlOption(const std::string& backend) {
  auto platform = gl::parsePlatformChoice(backend);
  if (!platform) return Error{"--gl expects auto, egl-device, egl-surfaceless or osmesa, got '" + backend + "'"};
  return *platform;
}

Result<std::unique_ptr<gl::GlContext>> openGlContext(const std::string& backend) {
  auto platform = parseGlOption(backend);
  if (!platform) return Error{platform.error()};
  auto context = gl::GlContext::create(*platform);
  if (!context) return Error{context.error()};
  const gl::GlInfo& info = (*context)->info();
  std::cerr << "specula: GL platform " << info.platform << ": " << info.renderer << ", " << info.version << "\n";
  return context;
}

}  // namespace specula::app
