#pragma once
// Sets the uniforms of shaders/common/shading.glsl; every pass that shades scene geometry uses it.
#include "gl/ShaderProgram.h"
#include "passes/FrameContext.h"
#include "passes/GpuTextures.h"
#include "scene/Scene.h"

namespace specula::passes {

void setSceneLighting(const gl::ShaderProgram& program, const scene::Scene& scene);
// Also binds the material's texture (GpuTextures) and points materialTexture at its unit.
void setMaterial(const gl::ShaderProgram& program, const scene::Material& material, const GpuTextures& textures);

// The uniforms of shaders/common/environment.glsl; binds the environment image, if any, on its unit.
void setEnvironment(const gl::ShaderProgram& program, const scene::Scene& scene, const GpuTextures& textures);

// viewForward and pixelAngle: the eye's ray cones, from which shading.glsl's pixelFootprint sizes the
// texture footprint of pixels shaded where a traced ray lands.
void setRayCone(const gl::ShaderProgram& program, const FrameContext& frame);

}  // namespace specula::passes
