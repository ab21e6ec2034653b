#pragma once
// Reflection-point math shared by exact solvers, error metrics and tests. The GLSL twin lives in
// shaders/common/reflection.glsl; tests run both on the same inputs.
#include <glm/glm.hpp>

namespace specula::math {

// How far R is from reflecting V towards O on a surface with unit normal N:
// 1 − dot(normalize(normalize(O − R) + normalize(V − R)), N); zero at an exact reflection point.
double reflectionError(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& eye, const glm::dvec3& vertex);

// V mirrored across the tangent plane at R with unit normal N; it lies |V − R| behind the mirror
// along the reflected ray, which is what makes it the "virtual vertex".
glm::dvec3 virtualVertex(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& vertex);

}  // namespace specula::math
