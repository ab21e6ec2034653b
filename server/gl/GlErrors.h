#pragma once
// GL status codes by name, for error messages: "GL_INVALID_OPERATION (0x0502)".
#include <string>

#include "gl/GlApi.h"

namespace specula::gl {

// A glGetError code.
std::string glErrorName(GLenum code);
// A glCheckFramebufferStatus result.
std::string framebufferStatusName(GLenum status);

}  // namespace specula::gl
