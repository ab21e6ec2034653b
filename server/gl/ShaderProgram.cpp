#include "gl/ShaderProgram.h"

#include <glm/gtc/type_ptr.hpp>
#include <set>
#include <utility>

#include "gl/EmbeddedShaders.h"

namespace specula::gl {

namespace {

constexpr int kMaxIncludeDepth = 8;

// Inlines `#include "file"` lines; each file is included once per shader, as with #pragma once.
Result<std::string> expand(std::string_view file, int depth, std::set<std::string_view>& included) {
  if (!included.insert(file).second) return std::string();
  const auto& files = embeddedShaderFiles();
  const auto found = files.find(file);
  if (found == files.end()) return Error{"shader file shaders/" + std::string(file) + " is not embedded (rebuild?)"};
  if (depth > kMaxIncludeDepth) return Error{"shaders/" + std::string(file) + ": #include nested too deeply"};
  std::string out;
  std::string_view text = found->second;
  constexpr std::string_view kInclude = "#include \"";
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end == std::string_view::npos ? text.size() : end + 1);
    text.remove_prefix(line.size());
    if (line.starts_with(kInclude)) {
      const std::size_t close = line.find('"', kInclude.size());
      if (close == std::string_view::npos) return Error{"shaders/" + std::string(file) + ": malformed #include"};
      auto expanded = expand(line.substr(kInclude.size(), close - kInclude.size()), depth + 1, included);
      if (!expanded) return expanded;
      out += expanded.value();
    } else {
      out += line;
    }
  }
  return out;
}

Result<GLenum> stageOf(std::string_view file) {
  if (file.ends_with(".vert")) return GLenum{GL_VERTEX_SHADER};
  if (file.ends_with(".tesc")) return GLenum{GL_TESS_CONTROL_SHADER};
  if (file.ends_with(".tese")) return GLenum{GL_TESS_EVALUATION_SHADER};
  if (file.ends_with(".geom")) return GLenum{GL_GEOMETRY_SHADER};
  if (file.ends_with(".frag")) return GLenum{GL_FRAGMENT_SHADER};
  if (file.ends_with(".comp")) return GLenum{GL_COMPUTE_SHADER};
  return Error{"shaders/" + std::string(file) + ": unknown stage (use .vert .tesc .tese .geom .frag .comp)"};
}

std::string infoLog(const GlApi& gl, GLuint object, bool isProgram) {
  GLint length = 0;
  (isProgram ? gl.GetProgramiv : gl.GetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  (isProgram ? gl.GetProgramInfoLog : gl.GetShaderInfoLog)(object, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

}  // namespace

Result<std::string> expandShaderSource(std::string_view file) {
  std::set<std::string_view> included;
  return expand(file, 0, included);
}

Result<ShaderProgram> ShaderProgram::build(const GlApi& gl, std::initializer_list<std::string_view> files) {
  ShaderProgram program(gl, gl.CreateProgram());
  std::vector<GLuint> shaders;
  auto release = [&] {
    for (GLuint shader : shaders) gl.DeleteShader(shader);
  };
  for (std::string_view file : files) {
    auto stage = stageOf(file);
    auto source = expandShaderSource(file);
    if (!stage || !source) {
      release();
      return Error{!stage ? stage.error() : source.error()};
    }
    const GLuint shader = gl.CreateShader(stage.value());
    shaders.push_back(shader);
    const char* text = source->c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint compiled = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (!compiled) {
      std::string log = infoLog(gl, shader, false);
      release();
      return Error{"shaders/" + std::string(file) + " failed to compile (line numbers count expanded #includes):\n" + log};
    }
    gl.AttachShader(program.id_, shader);
  }
  gl.LinkProgram(program.id_);
  release();
  GLint linked = GL_FALSE;
  gl.GetProgramiv(program.id_, GL_LINK_STATUS, &linked);
  if (!linked) {
    std::string names;
    for (std::string_view file : files) names += (names.empty() ? "" : ", ") + std::string(file);
    return Error{"shader program (" + names + ") failed to link:\n" + infoLog(gl, program.id_, true)};
  }
  return program;
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : gl_(other.gl_), id_(std::exchange(other.id_, 0)) {}
ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_) gl_->DeleteProgram(id_);
    gl_ = other.gl_;
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}
ShaderProgram::~ShaderProgram() {
  if (id_) gl_->DeleteProgram(id_);
}

void ShaderProgram::set(const char* name, int value) const { gl_->Uniform1i(gl_->GetUniformLocation(id_, name), value); }
void ShaderProgram::set(const char* name, unsigned value) const {
  gl_->Uniform1ui(gl_->GetUniformLocation(id_, name), value);
}
void ShaderProgram::set(const char* name, const glm::ivec2& value) const {
  gl_->Uniform2i(gl_->GetUniformLocation(id_, name), value.x, value.y);
}

void ShaderProgram::set(const char* name, const glm::ivec4& value) const {
  gl_->Uniform4i(gl_->GetUniformLocation(id_, name), value.x, value.y, value.z, value.w);
}
void ShaderProgram::set(const char* name, float value) const { gl_->Uniform1f(gl_->GetUniformLocation(id_, name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  gl_->Uniform2f(gl_->GetUniformLocation(id_, name), value.x, value.y);
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  gl_->Uniform3fv(gl_->GetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  gl_->Uniform4fv(gl_->GetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat3& value) const {
  gl_->UniformMatrix3fv(gl_->GetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  gl_->UniformMatrix4fv(gl_->GetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace specula::gl
