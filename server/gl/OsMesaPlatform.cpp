// OSMesa: Mesa's off-screen software GL, the fallback when EGL is absent.
// libOSMesa is opened at run time so GPU images without it still run.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>

#include "gl/GlPlatform.h"

namespace specula::gl {

namespace {

using CreateContextAttribs = OSMesaContext (*)(const int*, OSMesaContext);
using DestroyContext = void (*)(OSMesaContext);
using MakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using GetProcAddress = OSMESAproc (*)(const char*);

class OsMesaPlatform final : public GlPlatform {
 public:
  OsMesaPlatform(DestroyContext destroy, MakeCurrent makeCurrentFn, GetProcAddress getProc, OSMesaContext context)
      : destroy_(destroy), makeCurrent_(makeCurrentFn), getProc_(getProc), context_(context) {}
  ~OsMesaPlatform() override { destroy_(context_); }

  PlatformKind kind() const override { return PlatformKind::OsMesa; }
  void* procAddress(const char* name) const override { return reinterpret_cast<void*>(getProc_(name)); }
  Status makeCurrent() override {
    // OSMesa needs a colour buffer to be current; we render to FBOs, so 1×1 suffices.
    if (!makeCurrent_(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1)) return Error{"OSMesaMakeCurrent failed"};
    return {};
  }

 private:
  DestroyContext destroy_;
  MakeCurrent makeCurrent_;
  GetProcAddress getProc_;
  OSMesaContext context_;
  std::array<unsigned char, 4> pixel_{};
};

}  // namespace

Result<std::unique_ptr<GlPlatform>> createOsMesaPlatform() {
  void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  if (!library) library = dlopen("libOSMesa.so.6", RTLD_NOW | RTLD_LOCAL);
  if (!library) return Error{"libOSMesa.so.8 not found (install libosmesa6)"};
  auto create = reinterpret_cast<CreateContextAttribs>(dlsym(library, "OSMesaCreateContextAttribs"));
  auto destroy = reinterpret_cast<DestroyContext>(dlsym(library, "OSMesaDestroyContext"));
  auto makeCurrent = reinterpret_cast<MakeCurrent>(dlsym(library, "OSMesaMakeCurrent"));
  auto getProc = reinterpret_cast<GetProcAddress>(dlsym(library, "OSMesaGetProcAddress"));
  if (!create || !destroy || !makeCurrent || !getProc)
    return Error{"libOSMesa lacks OSMesaCreateContextAttribs (Mesa ≥ 12 needed)"};
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            4,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = create(attributes, nullptr);
  if (!context) return Error{"OSMesa could not create a GL 4.3 core context"};
  auto platform = std::make_unique<OsMesaPlatform>(destroy, makeCurrent, getProc, context);
  if (Status status = platform->makeCurrent(); !status) return Error{status.error()};
  return std::unique_ptr<GlPlatform>(std::move(platform));
}

}  // namespace specula::gl
