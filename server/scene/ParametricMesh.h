#pragma once
// Parametric surfaces as meshes: bicubic Bézier patches (B-spline surfaces arrive converted to them)
// keep their patches for the exact paths and carry a uniform grid of exact samples for the rest.
#include <string>
#include <vector>

#include "math/BezierPatch.h"
#include "scene/Mesh.h"

namespace specula::scene {

// Grid quads per patch side of a parametric mesh unless a scene says otherwise: fine enough that
// the grid's facets stay within about a pixel of the surface at the built-in scenes' distances.
inline constexpr int kDefaultPatchSegments = 16;

// The mesh of `patches`: each an (segments + 1)² grid of exact positions and normals (math::tessellatePatchGrid).
Mesh parametricMesh(std::string name, std::vector<math::BezierPatch> patches, int segments = kDefaultPatchSegments);

// Which patch triangle `triangle` of a parametric mesh lies on.
inline std::size_t patchOfTriangle(const Mesh& mesh, std::size_t triangle) {
  return triangle / (2 * static_cast<std::size_t>(mesh.patchSegments) * static_cast<std::size_t>(mesh.patchSegments));
}

}  // namespace specula::scene
