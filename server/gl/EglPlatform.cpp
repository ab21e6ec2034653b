// EGL platforms (GPU device and Mesa surfaceless) sharing one context set-up.
// libEGL is opened at run time so a machine without it still runs OSMesa, and says what is missing.
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstring>
#include <vector>

#include "gl/GlPlatform.h"

namespace specula::gl {

namespace {

constexpr int kGlMajor = 4, kGlMinor = 3;

// The EGL 1.5 core entry points, from libEGL.so.1; extensions come through eglGetProcAddress.
struct EglLibrary {
  void* handle = nullptr;
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLQUERYSTRINGPROC QueryString = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLTERMINATEPROC Terminate = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCHOOSECONFIGPROC ChooseConfig = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLGETERRORPROC GetError = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT = nullptr;
  PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceStringEXT = nullptr;

  static Result<EglLibrary> open() {
    EglLibrary egl;
    egl.handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!egl.handle) return Error{"libEGL.so.1 not found (install libegl1 and a driver: libegl-mesa0, or NVIDIA's)"};
    bool complete = true;
    auto symbol = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(egl.handle, name));
      complete = complete && fn != nullptr;
    };
    symbol(egl.GetProcAddress, "eglGetProcAddress");
    symbol(egl.QueryString, "eglQueryString");
    symbol(egl.Initialize, "eglInitialize");
    symbol(egl.Terminate, "eglTerminate");
    symbol(egl.BindAPI, "eglBindAPI");
    symbol(egl.ChooseConfig, "eglChooseConfig");
    symbol(egl.CreateContext, "eglCreateContext");
    symbol(egl.DestroyContext, "eglDestroyContext");
    symbol(egl.MakeCurrent, "eglMakeCurrent");
    symbol(egl.GetError, "eglGetError");
    if (!complete) return Error{"libEGL.so.1 lacks EGL 1.5 core functions"};
    egl.GetPlatformDisplayEXT =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl.GetProcAddress("eglGetPlatformDisplayEXT"));
    egl.QueryDevicesEXT = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl.GetProcAddress("eglQueryDevicesEXT"));
    egl.QueryDeviceStringEXT =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(egl.GetProcAddress("eglQueryDeviceStringEXT"));
    if (!egl.GetPlatformDisplayEXT) return Error{"EGL lacks EGL_EXT_platform_base"};
    return egl;
  }
};

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
    if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

std::string eglErrorText(EGLint code) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "EGL error 0x%04X", static_cast<unsigned>(code));
  return buffer;
}

class EglPlatform final : public GlPlatform {
 public:
  EglPlatform(PlatformKind kind, EglLibrary egl, EGLDisplay display) : kind_(kind), egl_(egl), display_(display) {}
  ~EglPlatform() override {
    if (context_ != EGL_NO_CONTEXT) {
      egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      egl_.DestroyContext(display_, context_);
    }
    egl_.Terminate(display_);
    // libEGL stays loaded: drivers register atexit handlers that must outlive us.
  }

  PlatformKind kind() const override { return kind_; }
  void* procAddress(const char* name) const override { return reinterpret_cast<void*>(egl_.GetProcAddress(name)); }
  Status makeCurrent() override {
    if (!egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      return Error{"eglMakeCurrent failed: " + eglErrorText(egl_.GetError())};
    return {};
  }

  // Initializes the display and creates a surfaceless GL core context on it.
  Status createContext() {
    EGLint major = 0, minor = 0;
    if (!egl_.Initialize(display_, &major, &minor))
      return Error{"eglInitialize failed: " + eglErrorText(egl_.GetError())};
    if (!hasExtension(egl_.QueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
      return Error{"the EGL display lacks EGL_KHR_surfaceless_context"};
    if (!egl_.BindAPI(EGL_OPENGL_API)) return Error{"eglBindAPI(EGL_OPENGL_API) failed: desktop GL not offered"};
    // SURFACE_TYPE defaults to EGL_WINDOW_BIT, which headless displays lack: ask for no surface at all.
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!egl_.ChooseConfig(display_, configAttributes, &config, 1, &configCount) || configCount < 1)
      return Error{"no EGL config supports desktop OpenGL"};
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        kGlMajor,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        kGlMinor,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_CONTEXT_OPENGL_DEBUG,
                                        glDebugOutputRequested() ? EGL_TRUE : EGL_FALSE,
                                        EGL_NONE};
    context_ = egl_.CreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
    if (context_ == EGL_NO_CONTEXT)
      return Error{"could not create a GL " + std::to_string(kGlMajor) + "." + std::to_string(kGlMinor) +
                   " core context: " + eglErrorText(egl_.GetError())};
    return makeCurrent();
  }

 private:
  PlatformKind kind_;
  EglLibrary egl_;
  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
};

Result<std::unique_ptr<GlPlatform>> finish(PlatformKind kind, const EglLibrary& egl, EGLDisplay display) {
  auto platform = std::make_unique<EglPlatform>(kind, egl, display);
  if (Status status = platform->createContext(); !status) return Error{status.error()};
  return std::unique_ptr<GlPlatform>(std::move(platform));
}

}  // namespace

Result<std::unique_ptr<GlPlatform>> createEglDevicePlatform() {
  auto egl = EglLibrary::open();
  if (!egl) return Error{egl.error()};
  if (!egl->QueryDevicesEXT || !egl->QueryDeviceStringEXT)
    return Error{"EGL lacks EGL_EXT_device_enumeration/EGL_EXT_device_query"};
  EGLint count = 0;
  if (!egl->QueryDevicesEXT(0, nullptr, &count) || count <= 0) return Error{"EGL reports no devices"};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  egl->QueryDevicesEXT(count, devices.data(), &count);
  std::string rejected;
  for (EGLDeviceEXT device : devices) {
    // Mesa lists llvmpipe as a "software device": that is the surfaceless path's job, not a GPU.
    const char* extensions = egl->QueryDeviceStringEXT(device, EGL_EXTENSIONS);
    if (hasExtension(extensions, "EGL_MESA_device_software")) {
      rejected = "only a software device (Mesa llvmpipe) was found";
      continue;
    }
    EGLDisplay display = egl->GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY) continue;
    auto platform = finish(PlatformKind::EglDevice, *egl, display);
    if (platform) return platform;
    rejected = platform.error();
  }
  return Error{"no GPU EGL device gave a context: " + (rejected.empty() ? std::string("none usable") : rejected)};
}

Result<std::unique_ptr<GlPlatform>> createEglSurfacelessPlatform() {
  auto egl = EglLibrary::open();
  if (!egl) return Error{egl.error()};
  if (!hasExtension(egl->QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
    return Error{"EGL lacks EGL_MESA_platform_surfaceless (install libegl-mesa0)"};
  EGLDisplay display = egl->GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) return Error{"no surfaceless EGL display: " + eglErrorText(egl->GetError())};
  return finish(PlatformKind::EglSurfaceless, *egl, display);
}

}  // namespace specula::gl
