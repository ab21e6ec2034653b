// GL status codes in messages: by name, and in hex as the GL headers and documentation write them.
#include <gtest/gtest.h>

#include "gl/GlErrors.h"

namespace specula {
namespace {

TEST(GlErrors, ErrorCodesAreNamedInHex) {
  EXPECT_EQ(gl::glErrorName(GL_INVALID_ENUM), "GL_INVALID_ENUM (0x0500)");
  EXPECT_EQ(gl::glErrorName(GL_INVALID_OPERATION), "GL_INVALID_OPERATION (0x0502)");
  EXPECT_EQ(gl::glErrorName(GL_OUT_OF_MEMORY), "GL_OUT_OF_MEMORY (0x0505)");
}

TEST(GlErrors, FramebufferStatusesAreNamedInHex) {
  EXPECT_EQ(gl::framebufferStatusName(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT),
            "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (0x8CD6)");
  EXPECT_EQ(gl::framebufferStatusName(GL_FRAMEBUFFER_UNSUPPORTED), "GL_FRAMEBUFFER_UNSUPPORTED (0x8CDD)");
}

TEST(GlErrors, AnUnknownCodeStillShowsItsValue) {
  EXPECT_EQ(gl::glErrorName(0x1234), "unknown (0x1234)");
  EXPECT_EQ(gl::framebufferStatusName(GL_INVALID_ENUM), "unknown (0x0500)");  // a status is no error code
}

}  // namespace
}  // namespace specula
