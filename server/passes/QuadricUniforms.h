#pragma once
// Sets the uniforms of shaders/common/quadric.glsl for one mirror: the G-buffer pass and the search
// both work on the exact surface of an analytic mirror.
#include <glm/glm.hpp>

#include "gl/ShaderProgram.h"
#include "scene/MirrorInfo.h"

namespace specula::passes {

// Whether the mirror's surface is an exact closed quadric, drawn through its proxy box
// (shaders/common/quadric-proxy.vert) rather than its mesh.
bool hasExactQuadric(const scene::MirrorInfo& mirror);

// Vertices of the proxy box: draw them as triangles with no attributes bound.
inline constexpr int kQuadricProxyVertices = 36;

// Sets `analytic` to 1 and the quadric when the mirror has an exact shape and its mesh is that
// whole closed shape; to 0 otherwise (the mesh is the surface).
void setMirrorQuadric(const gl::ShaderProgram& program, const scene::MirrorInfo& mirror, const glm::mat4& objectToWorld);

}  // namespace specula::passes
