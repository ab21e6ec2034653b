#pragma once
// A linked GL program built from embedded shaders/ files; the file extension names the stage
// (.vert .geom .frag .comp). Files may `#include "common/x.glsl"` after their #version line.
#include <glm/glm.hpp>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"
#include "gl/GlApi.h"

namespace specula::gl {

class ShaderProgram {
 public:
  static Result<ShaderProgram> build(const GlApi& gl, std::initializer_list<std::string_view> files);

  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  ~ShaderProgram();

  GLuint id() const { return id_; }
  void use() const { gl_->UseProgram(id_); }

  // Uniform setters for the program in use; unknown names are ignored, as GL does for location -1.
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
  const GlApi* gl_;
  GLuint id_ = 0;
};

// The source of a shaders/ file with its #includes expanded (exposed for tests).
Result<std::string> expandShaderSource(std::string_view file);

}  // namespace specula::gl
