// Shader errors that say where they are: a compile error names the file it is in, included or not, with
// that file's own line; a uniform name the program's sources never declare is reported, not ignored.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "SoftwarePlatforms.h"
#include "gl/GlContext.h"
#include "gl/ShaderProgram.h"
#include "gl/ShaderSource.h"

namespace specula {
namespace {

// Every test in this binary fails when it sets a uniform its program does not declare: a renamed
// uniform would otherwise be set nowhere, silently.
class UnknownUniformsFail : public ::testing::Environment {
 public:
  void SetUp() override {
    gl::setUnknownUniformHandler([](const std::string& message) { ADD_FAILURE() << message; });
  }
};
[[maybe_unused]] const auto* const kUnknownUniformsFail = ::testing::AddGlobalTestEnvironment(new UnknownUniformsFail);

// The top file includes one file twice (the second include is skipped) and one that includes it too.
const gl::ShaderFiles kSources = {
    {"test/top.frag",
     "#version 430 core\n"
     "#include \"test/lighting.glsl\"\n"
     "#include \"test/lighting.glsl\"\n"
     "#include \"test/surface.glsl\"\n"
     "out vec4 colour;\n"
     "void main() { colour = vec4(surface() * light(), 1.0); }\n"},
    {"test/lighting.glsl",
     "// A first line that is a comment.\n"
     "uniform float brightness;\n"
     "float light() { return brightness; }\n"},
    {"test/surface.glsl",
     "#include \"test/lighting.glsl\"\n"
     "uniform vec3 albedo, unusedTint;\n"
     "uniform float weights[2];\n"
     "vec3 surface() { return albedo * weights[1]; }\n"},
};

// `kSources` with `line` (1-based) of `file` replaced.
gl::ShaderFiles withLine(const std::string& file, int line, const std::string& replacement,
                         std::vector<std::string>& storage) {
  std::string text(kSources.at(file));
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  text.replace(start, text.find('\n', start) - start, replacement);
  storage.push_back(std::move(text));
  gl::ShaderFiles sources = kSources;
  sources[file] = storage.back();
  return sources;
}

class ShaderErrorsTest : public ::testing::TestWithParam<gl::PlatformChoice> {
 protected:
  void SetUp() override {
    auto context = gl::GlContext::create(GetParam());
    ASSERT_TRUE(context) << context.error();
    context_ = std::move(*context);
  }

  Result<gl::ShaderProgram> build(const gl::ShaderFiles& sources) {
    return gl::ShaderProgram::build(context_->api(), {"test/top.frag"}, sources);
  }

  std::unique_ptr<gl::GlContext> context_;
};

TEST_P(ShaderErrorsTest, TheSourcesCompileAsTheyAre) {
  auto program = build(kSources);
  EXPECT_TRUE(program) << program.error();
}

TEST_P(ShaderErrorsTest, AnErrorInAnIncludedFileNamesThatFileAndItsOwnLine) {
  std::vector<std::string> storage;
  auto program = build(withLine("test/surface.glsl", 4, "vec3 surface() { return albedo * undeclared; }", storage));
  ASSERT_FALSE(program);
  EXPECT_NE(program.error().find("shaders/test/surface.glsl:4:"), std::string::npos) << program.error();
}

TEST_P(ShaderErrorsTest, AnErrorInTheFirstIncludedFileNamesItsOwnLine) {
  std::vector<std::string> storage;
  auto program = build(withLine("test/lighting.glsl", 3, "float light() { return undeclared; }", storage));
  ASSERT_FALSE(program);
  EXPECT_NE(program.error().find("shaders/test/lighting.glsl:3:"), std::string::npos) << program.error();
}

TEST_P(ShaderErrorsTest, AnErrorAfterTheIncludesCountsTheIncludersOwnLines) {
  std::vector<std::string> storage;
  auto program = build(withLine("test/top.frag", 6, "void main() { colour = undeclared; }", storage));
  ASSERT_FALSE(program);
  EXPECT_NE(program.error().find("shaders/test/top.frag:6:"), std::string::npos) << program.error();
}

TEST_P(ShaderErrorsTest, AUniformDeclaredButOptimisedAwayIsNoError) {
  auto program = build(kSources);
  ASSERT_TRUE(program) << program.error();
  program->use();
  EXPECT_EQ(context_->api().GetUniformLocation(program->id(), "unusedTint"), -1);
  program->set("unusedTint", glm::vec3(1.0f));  // the environment fails the test if this counts as unknown
  program->set("weights[1]", 0.5f);
  program->set("brightness", 1.0f);
}

std::vector<std::string> reported;
void recordUnknownUniform(const std::string& message) { reported.push_back(message); }

TEST_P(ShaderErrorsTest, AUniformNoSourceDeclaresIsReportedWithTheProgramsFiles) {
  auto program = build(kSources);
  ASSERT_TRUE(program) << program.error();
  program->use();
  reported.clear();
  const gl::UnknownUniformHandler failing = gl::setUnknownUniformHandler(recordUnknownUniform);
  program->set("brightnes", 1.0f);
  program->set("albedo", glm::vec3(1.0f));
  gl::setUnknownUniformHandler(failing);
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_NE(reported[0].find("\"brightnes\""), std::string::npos) << reported[0];
  EXPECT_NE(reported[0].find("test/top.frag"), std::string::npos) << reported[0];
}

INSTANTIATE_TEST_SUITE_P(Software, ShaderErrorsTest, specula::testing::kSoftwarePlatforms,
                         specula::testing::platformTestName);

TEST(ShaderErrors, AnIncludeBeforeVersionIsRefused) {
  gl::ShaderFiles sources = kSources;
  sources["test/top.frag"] = "#include \"test/lighting.glsl\"\n#version 430 core\n";
  auto expanded = gl::expandShader("test/top.frag", sources);
  ASSERT_FALSE(expanded);
  EXPECT_NE(expanded.error().find("#include before #version"), std::string::npos) << expanded.error();
}

TEST(ShaderErrors, DriverLogPositionsBecomeFileAndLine) {
  const std::vector<std::string> files = {"a/top.frag", "common/shading.glsl"};
  EXPECT_EQ(gl::attributeShaderLog("1:42(7): error: `x' undeclared\n", files),
            "shaders/common/shading.glsl:42:7: error: `x' undeclared\n");  // Mesa
  EXPECT_EQ(gl::attributeShaderLog("0(12) : error C1008: undefined variable \"x\"", files),
            "shaders/a/top.frag:12: error C1008: undefined variable \"x\"");  // NVIDIA
  EXPECT_EQ(gl::attributeShaderLog("7:3(1): error: out of range\nlink failed", files),
            "7:3(1): error: out of range\nlink failed");  // no such source string: left as it is
}

TEST(ShaderErrors, DeclaredUniformsAreFoundInEachDeclarationForm) {
  const auto names = gl::declaredUniforms(
      "uniform vec3 a, b;  // two\n"
      "layout(rgba32f, binding = 0) uniform writeonly image2DArray c;\n"
      "uniform vec4 d[kMaxLights]; uniform int e;\n"
      "float notAUniform;\n"
      "// uniform int commentedOut;\n");
  EXPECT_EQ(names, (std::set<std::string, std::less<>>{"a", "b", "c", "d", "e"}));
}

}  // namespace
}  // namespace specula
