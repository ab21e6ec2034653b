#include "gl/GlApi.h"

namespace specula::gl {

std::string GlApi::load(ProcLoader loader, void* user) {
  std::string missing;
#define SPECULA_GL_LOAD(type, name)                        \
  name = reinterpret_cast<type>(loader("gl" #name, user)); \
  if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
  SPECULA_GL_FUNCTIONS(SPECULA_GL_LOAD)
#undef SPECULA_GL_LOAD
  return missing;
}

}  // namespace specula::gl
