#pragma once
// Normals for imported meshes that come without them.
#include "scene/Mesh.h"

namespace specula::scene {

// Area-weighted smooth normals. Vertices at the same position share one normal, so uv seams stay
// invisible; a vertex touched only by degenerate triangles gets +y.
void computeSmoothNormals(Mesh& mesh);

// Gives every triangle its own three vertices carrying the face normal (glTF's rule for primitives
// without normals). Triples the vertex count; a degenerate triangle gets +y.
void makeFlatShaded(Mesh& mesh);

}  // namespace specula::scene
