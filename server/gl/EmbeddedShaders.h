#pragma once
#include <map>
#include <string_view>

namespace specula::gl {

// GLSL sources from shaders/, keyed by path relative to it ("scene/scene.frag"). Built by CMake.
const std::map<std::string_view, std::string_view>& embeddedShaderFiles();

}  // namespace specula::gl
