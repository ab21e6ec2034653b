#include "gl/ShaderProgram.h"

#include <cstdio>
#include <cstdlib>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

#include "gl/EmbeddedShaders.h"

namespace specula::gl {

namespace {

#ifdef NDEBUG
UnknownUniformHandler unknownUniformHandler = nullptr;
#else
void abortOnUnknownUniform(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::abort();
}
UnknownUniformHandler unknownUniformHandler = abortOnUnknownUniform;
#endif

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

UnknownUniformHandler setUnknownUniformHandler(UnknownUniformHandler handler) {
  return std::exchange(unknownUniformHandler, handler);
}

Result<std::string> expandShaderSource(std::string_view file) {
  auto expanded = expandShader(file, embeddedShaderFiles());
  if (!expanded) return Error{expanded.error()};
  return std::move(expanded->text);
}

Result<ShaderProgram> ShaderProgram::build(const GlApi& gl, std::initializer_list<std::string_view> files) {
  return build(gl, files, embeddedShaderFiles());
}

Result<ShaderProgram> ShaderProgram::build(const GlApi& gl, std::initializer_list<std::string_view> files,
                                           const ShaderFiles& sources) {
  ShaderProgram program(gl, gl.CreateProgram());
  for (std::string_view file : files) program.files_ += (program.files_.empty() ? "" : ", ") + std::string(file);
  std::vector<GLuint> shaders;
  auto release = [&] {
    for (GLuint shader : shaders) gl.DeleteShader(shader);
  };
  for (std::string_view file : files) {
    auto stage = stageOf(file);
    auto source = expandShader(file, sources);
    if (!stage || !source) {
      release();
      return Error{!stage ? stage.error() : source.error()};
    }
    const GLuint shader = gl.CreateShader(stage.value());
    shaders.push_back(shader);
    const char* text = source->text.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint compiled = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (!compiled) {
      std::string log = attributeShaderLog(infoLog(gl, shader, false), source->files);
      release();
      return Error{"shaders/" + std::string(file) + " failed to compile:\n" + log};
    }
    gl.AttachShader(program.id_, shader);
    program.declaredUniforms_.merge(declaredUniforms(source->text));
  }
  gl.LinkProgram(program.id_);
  release();
  GLint linked = GL_FALSE;
  gl.GetProgramiv(program.id_, GL_LINK_STATUS, &linked);
  if (!linked)
    return Error{"shader program (" + program.files_ + ") failed to link:\n" + infoLog(gl, program.id_, true)};
  return program;
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : gl_(other.gl_),
      id_(std::exchange(other.id_, 0)),
      files_(std::move(other.files_)),
      declaredUniforms_(std::move(other.declaredUniforms_)) {}
ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_) gl_->DeleteProgram(id_);
    gl_ = other.gl_;
    id_ = std::exchange(other.id_, 0);
    files_ = std::move(other.files_);
    declaredUniforms_ = std::move(other.declaredUniforms_);
  }
  return *this;
}
ShaderProgram::~ShaderProgram() {
  if (id_) gl_->DeleteProgram(id_);
}

GLint ShaderProgram::location(const char* name) const {
  const GLint location = gl_->GetUniformLocation(id_, name);
  if (location != -1 || !unknownUniformHandler) return location;
  std::string_view declared(name);
  declared = declared.substr(0, declared.find_first_of("[."));  // "light[2]" is declared as light
  if (!declaredUniforms_.contains(declared))
    unknownUniformHandler("uniform \"" + std::string(name) + "\" is declared in none of " + files_ + " (renamed?)");
  return location;
}

void ShaderProgram::set(const char* name, int value) const { gl_->Uniform1i(location(name), value); }
void ShaderProgram::set(const char* name, unsigned value) const { gl_->Uniform1ui(location(name), value); }
void ShaderProgram::set(const char* name, const glm::ivec2& value) const {
  gl_->Uniform2i(location(name), value.x, value.y);
}
void ShaderProgram::set(const char* name, const glm::ivec4& value) const {
  gl_->Uniform4i(location(name), value.x, value.y, value.z, value.w);
}
void ShaderProgram::set(const char* name, float value) const { gl_->Uniform1f(location(name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  gl_->Uniform2f(location(name), value.x, value.y);
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  gl_->Uniform3fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  gl_->Uniform4fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat3& value) const {
  gl_->UniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  gl_->UniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace specula::gl
