#pragma once
// Reflection-point math shared by exact solvers, error metrics and tests. The GLSL twin lives in
// shaders/common/reflection.glsl; tests run both on the same inputs.
#include <glm/glm.hpp>

namespace specula::math {

// How far R is from reflecting V towards O on a surface with unit normal N:
// 1 − dot(normalize(normalize(O − R) + normalize(V − R)), N); zero at an exact reflection point.
double reflectionError(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& eye, const glm::dvec3& vertex);

// The virtual vertex of V reflected at R: on the eye's ray through R, |O − R| + |R − V| from the eye.
// For an exact R this is V mirrored across the tangent plane at R (mirrorAcrossPlane); unlike that
// it needs no normal and always projects where R does.
glm::dvec3 virtualVertex(const glm::dvec3& eye, const glm::dvec3& r, const glm::dvec3& vertex);

// V mirrored across the plane through R with unit normal N: where a vertex hidden behind the
// mirror's silhouette (region C) is placed, just outside the silhouette.
glm::dvec3 mirrorAcrossPlane(const glm::dvec3& r, const glm::dvec3& n, const glm::dvec3& vertex);

}  // namespace specula::math
