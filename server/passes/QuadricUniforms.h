#pragma once
// Sets the uniforms of shaders/common/quadric.glsl for one mirror: the G-buffer pass and the search
// both work on the exact surface of an analytic mirror.
#include <glm/glm.hpp>

#include "gl/ShaderProgram.h"
#include "scene/MirrorInfo.h"

namespace specula::passes {

// Vertices of the proxy box: draw them as triangles with no attributes bound.
inline constexpr int kQuadricProxyVertices = 36;

// Sets `analytic` to 1 and the quadric when the mirror's surface is its exact quadric
// (MirrorInfo::exactQuadric); to 0 otherwise (the mesh is the surface).
void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror, const glm::mat4& objectToWorld);

}  // namespace specula::passes
