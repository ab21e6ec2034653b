#pragma once
// Sets the uniforms of shaders/common/shading.glsl; every pass that shades scene geometry uses it.
#include "gl/ShaderProgram.h"
#include "scene/Scene.h"

namespace specula::passes {

void setSceneLighting(const gl::ShaderProgram& program, const scene::Scene& scene);
void setMaterial(const gl::ShaderProgram& program, const scene::Material& material);

}  // namespace specula::passes
