#include "gl/GlErrors.h"

#include <cstdio>
#include <span>
#include <utility>

namespace specula::gl {

namespace {

#define SPECULA_GL_CODE(name) \
  std::pair<GLenum, const char*> { name, #name }

constexpr std::pair<GLenum, const char*> kErrors[] = {
    SPECULA_GL_CODE(GL_NO_ERROR),       SPECULA_GL_CODE(GL_INVALID_ENUM),
    SPECULA_GL_CODE(GL_INVALID_VALUE),  SPECULA_GL_CODE(GL_INVALID_OPERATION),
    SPECULA_GL_CODE(GL_STACK_OVERFLOW), SPECULA_GL_CODE(GL_STACK_UNDERFLOW),
    SPECULA_GL_CODE(GL_OUT_OF_MEMORY),  SPECULA_GL_CODE(GL_INVALID_FRAMEBUFFER_OPERATION),
    SPECULA_GL_CODE(GL_CONTEXT_LOST),
};

constexpr std::pair<GLenum, const char*> kFramebufferStatuses[] = {
    SPECULA_GL_CODE(GL_FRAMEBUFFER_COMPLETE),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_UNDEFINED),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_UNSUPPORTED),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE),
    SPECULA_GL_CODE(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS),
};

#undef SPECULA_GL_CODE

// "NAME (0x0502)", in hex as the GL headers write codes; "unknown" for a code not in `names`.
std::string named(GLenum code, std::span<const std::pair<GLenum, const char*>> names) {
  const char* name = "unknown";
  for (const auto& [known, knownName] : names)
    if (known == code) name = knownName;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(code));
  return std::string(name) + " (" + hex + ")";
}

}  // namespace

std::string glErrorName(GLenum code) { return named(code, kErrors); }
std::string framebufferStatusName(GLenum status) { return named(status, kFramebufferStatuses); }

}  // namespace specula::gl
