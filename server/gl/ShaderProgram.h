#pragma once
// A linked GL program built from embedded shaders/ files; the file extension names the stage
// (.vert .geom .frag .comp). Files may `#include "common/x.glsl"` after their #version line; compile
// errors name the file and line they are in, included or not.
#include <glm/glm.hpp>
#include <initializer_list>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"
#include "gl/ShaderSource.h"

namespace specula::gl {

class ShaderProgram {
 public:
  static Result<ShaderProgram> build(const GlApi& gl, std::initializer_list<std::string_view> files);
  // The same from `sources` instead of the embedded shaders/ files.
  static Result<ShaderProgram> build(const GlApi& gl, std::initializer_list<std::string_view> files,
                                     const ShaderFiles& sources);

  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram();

  GLuint id() const { return id_; }
  void use() const { gl_->UseProgram(id_); }

  // Uniform setters for the program in use. A uniform declared but optimised away is ignored, as GL
  // does for location -1; a name the sources do not declare goes to the unknown-uniform handler.
  void set(const char* name, int value) const;
  void set(const char* name, unsigned value) const;
  void set(const char* name, const glm::ivec2& value) const;
  void set(const char* name, const glm::ivec4& value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat3& value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  ShaderProgram(const GlApi& gl, GLuint id) : gl_(&gl), id_(id) {}
  GLint location(const char* name) const;

  const GlApi* gl_;
  GLuint id_ = 0;
  std::string files_;                                    // "a.vert, b.frag", for messages
  std::set<std::string, std::less<>> declaredUniforms_;  // by every stage's source
};

// Called by ShaderProgram::set with a message naming a uniform its program's sources do not declare
// (renamed or misspelt). Debug builds abort; other builds ignore it unless a handler is set (tests
// set one that fails the test). Returns the handler it replaces.
using UnknownUniformHandler = void (*)(const std::string& message);
UnknownUniformHandler setUnknownUniformHandler(UnknownUniformHandler handler);

// The source of a shaders/ file with its #includes expanded (exposed for tests).
Result<std::string> expandShaderSource(std::string_view file);

}  // namespace specula::gl
