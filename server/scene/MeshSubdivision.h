#pragma once
// Splits long edges of a mesh before it is used, as Estalella et al. 2006 did at load: a virtual
// object is flat between its vertices, so a large triangle near a mirror (a table top under a bowl)
// needs vertices where its reflection bends, which adaptive tessellation alone reaches only in
// many rounds.
#include <cstddef>
#include <optional>

#include "scene/Mesh.h"

namespace specula::scene {

// Splits every edge longer than `maxEdgeLength` (object-space metres) at its midpoint, round after
// round, until none is; each edge is decided alone and triangles follow the conforming pattern of
// their split edges (1, 2 or 3 → 2, 3 or 4 triangles), so no crack opens. Normals and uv are
// interpolated (normals renormalised). nullopt when the result would exceed `maxTriangles`.
std::optional<Mesh> subdivideLongEdges(const Mesh& mesh, float maxEdgeLength, std::size_t maxTriangles);

}  // namespace specula::scene
