#include <gtest/gtest.h>

#include <cstdlib>

#include "gl/GlContext.h"
#include "gl/ShaderProgram.h"
#include "scene/Scene.h"
#include "SoftwarePlatforms.h"

using namespace specula;

class GlPlatformTest : public ::testing::TestWithParam<gl::PlatformChoice> {};

TEST_P(GlPlatformTest, CreatesCoreContextOfAtLeast43AndReportsItsRenderer) {
  auto context = gl::GlContext::create(GetParam());
  ASSERT_TRUE(context) << context.error();
  const gl::GlInfo& info = (*context)->info();
  EXPECT_EQ(info.platform, GetParam() == gl::PlatformChoice::OsMesa ? "osmesa" : "egl-surfaceless");
  EXPECT_FALSE(info.renderer.empty());
  GLint major = 0, minor = 0;
  (*context)->api().GetIntegerv(GL_MAJOR_VERSION, &major);
  (*context)->api().GetIntegerv(GL_MINOR_VERSION, &minor);
  EXPECT_GE(major * 10 + minor, 43) << info.version;
}

TEST_P(GlPlatformTest, CompilesEveryEmbeddedShaderStageWithoutErrors) {
  auto context = gl::GlContext::create(GetParam());
  ASSERT_TRUE(context) << context.error();
  auto program = gl::ShaderProgram::build((*context)->api(), {"scene/scene.vert", "scene/scene.frag"});
  EXPECT_TRUE(program) << program.error();
}

TEST_P(GlPlatformTest, ShaderLightArraysHoldExactlyTheScenesLightLimit) {
  auto context = gl::GlContext::create(GetParam());
  ASSERT_TRUE(context) << context.error();
  const gl::GlApi& api = (*context)->api();
  auto program = gl::ShaderProgram::build(api, {"scene/scene.vert", "scene/scene.frag"});
  ASSERT_TRUE(program) << program.error();
  const std::string last = "lightVector[" + std::to_string(scene::kMaxLights - 1) + "]";
  const std::string beyond = "lightVector[" + std::to_string(scene::kMaxLights) + "]";
  EXPECT_NE(api.GetUniformLocation(program->id(), last.c_str()), -1);
  EXPECT_EQ(api.GetUniformLocation(program->id(), beyond.c_str()), -1);
}

TEST_P(GlPlatformTest, ReportsMissingShaderFileByName) {
  auto context = gl::GlContext::create(GetParam());
  ASSERT_TRUE(context) << context.error();
  auto program = gl::ShaderProgram::build((*context)->api(), {"nope/missing.frag"});
  ASSERT_FALSE(program);
  EXPECT_NE(program.error().find("shaders/nope/missing.frag"), std::string::npos) << program.error();
}

// SPECULA_GL_DEBUG=1 is how a deployer sees what a driver complains about (on NVIDIA: shader
// recompiles, buffers moved to host memory): an error reaches stderr once, and nothing without it.
// OSMesa has no debug contexts and Mesa stays silent in others, which the line that turns it on says.
TEST_P(GlPlatformTest, DriverMessagesReachStderrOnlyWhenAskedFor) {
  const auto stderrAroundABadCall = [&](bool asked) {
    if (asked) ::setenv("SPECULA_GL_DEBUG", "1", 1);
    ::testing::internal::CaptureStderr();
    auto context = gl::GlContext::create(GetParam());
    ::unsetenv("SPECULA_GL_DEBUG");
    if (context) {
      for (int i = 0; i < 3; ++i) (*context)->api().BindBuffer(0xDEAD, 0);  // GL_INVALID_ENUM, three times
      EXPECT_EQ((*context)->api().GetError(), static_cast<GLenum>(GL_INVALID_ENUM));
    }
    std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(context) << context.error();
    return printed;
  };
  EXPECT_EQ(stderrAroundABadCall(false), "");
  const std::string printed = stderrAroundABadCall(true);
  if (GetParam() == gl::PlatformChoice::OsMesa) {
    EXPECT_NE(printed.find("gave no debug context"), std::string::npos) << printed;
    return;
  }
  const std::size_t first = printed.find("GL debug (");
  ASSERT_NE(first, std::string::npos) << printed;
  EXPECT_NE(printed.find("type 0x824C"), std::string::npos) << "GL_DEBUG_TYPE_ERROR: " << printed;
  EXPECT_EQ(printed.find("GL debug (", first + 1), std::string::npos) << "each message once: " << printed;
}

INSTANTIATE_TEST_SUITE_P(Software, GlPlatformTest, specula::testing::kSoftwarePlatforms,
                         specula::testing::platformTestName);

TEST(GlPlatformChoice, AutoFindsAPlatformOnThisMachine) {
  auto context = gl::GlContext::create(gl::PlatformChoice::Auto);
  EXPECT_TRUE(context) << context.error();
}

TEST(GlPlatformChoice, EglDeviceNeverSettlesForTheSoftwareRasterizer) {
  // On a GPU machine this yields the GPU; on a CPU-only one it must fail and say why, not pick llvmpipe.
  auto context = gl::GlContext::create(gl::PlatformChoice::EglDevice);
  if (context) {
    EXPECT_EQ((*context)->info().renderer.find("llvmpipe"), std::string::npos);
  } else {
    EXPECT_NE(context.error().find("egl-device:"), std::string::npos) << context.error();
    EXPECT_NE(context.error().find("install"), std::string::npos) << context.error();
  }
}

TEST(GlPlatformChoice, ParsesTheFourNamesAndRejectsOthers) {
  EXPECT_EQ(gl::parsePlatformChoice("auto"), gl::PlatformChoice::Auto);
  EXPECT_EQ(gl::parsePlatformChoice("egl-device"), gl::PlatformChoice::EglDevice);
  EXPECT_EQ(gl::parsePlatformChoice("egl-surfaceless"), gl::PlatformChoice::EglSurfaceless);
  EXPECT_EQ(gl::parsePlatformChoice("osmesa"), gl::PlatformChoice::OsMesa);
  EXPECT_FALSE(gl::parsePlatformChoice("glx").has_value());
}

TEST(ShaderSource, ExpandsIncludesInPlace) {
  auto source = gl::expandShaderSource("scene/scene.frag");
  ASSERT_TRUE(source) << source.error();
  EXPECT_EQ(source->find("#include"), std::string::npos);
  EXPECT_NE(source->find("vec3 shadeSurface("), std::string::npos);
  EXPECT_EQ(source->rfind("#version 430 core", 0), 0u) << "#version must stay the first line";
}
