#pragma once
// Sets the uniforms of the exact mirror shapes for one mirror: shaders/common/quadric.glsl (the
// G-buffer pass and the search both work on the exact surface of an analytic mirror) and
// shaders/common/extrusion.glsl (the search solves an extrusion mirror's reflection points exactly).
#include <glm/glm.hpp>

#include "gl/ShaderProgram.h"
#include "scene/MirrorInfo.h"

namespace specula::passes {

// Vertices of the proxy box: draw them as triangles with no attributes bound.
inline constexpr int kQuadricProxyVertices = 36;

// Sets `analytic` to 1 and the quadric when the mirror's surface is its exact quadric
// (MirrorInfo::exactQuadric); to 0 otherwise (the mesh is the surface).
void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror,
                      const glm::mat4& objectToWorld);

// Sets `extrusion` to 1 and the world extrusion when the mirror declares one and `solve` is on
// (ReflectionSettings::solveExtrusions); to 0 otherwise, and when its transform flattens the profile.
void setMirrorExtrusion(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror,
                        const glm::mat4& objectToWorld, bool solve);

}  // namespace specula::passes
