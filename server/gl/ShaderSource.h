#pragma once
// GLSL source text from shaders/ files: `#include "file"` expanded with #line directives, so a driver's
// compile log can name the included file and its own line; and the uniforms a source declares.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/Result.h"

namespace specula::gl {

// Shader files by path relative to shaders/, as embeddedShaderFiles() holds them.
using ShaderFiles = std::map<std::string_view, std::string_view>;

struct ExpandedShader {
  std::string text;                // each included file inlined between `#line 1 S` and `#line N S'`
  std::vector<std::string> files;  // source-string number S → path relative to shaders/; 0 is the top file
};

// `file` with its #includes expanded, each file once (as with #pragma once); an include must follow #version.
Result<ExpandedShader> expandShader(std::string_view file, const ShaderFiles& files);

// A driver's compile log with each position "S:LINE(COL):" (Mesa) or "S(LINE) :" (NVIDIA) rewritten as
// "shaders/path:LINE:COL:" by `files`, the source-string table of expandShader.
std::string attributeShaderLog(std::string_view log, const std::vector<std::string>& files);

// The names `source` declares as default-block uniforms (`[layout(...)] uniform type a, b[4];`), arrays
// by their bare name.
std::set<std::string, std::less<>> declaredUniforms(std::string_view source);

}  // namespace specula::gl
