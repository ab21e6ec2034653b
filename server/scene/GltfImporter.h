#pragma once
// glTF 2.0 import (tinygltf) of one mesh's triangles, from .gltf (JSON) or .glb (binary) files.
#include <cstddef>
#include <filesystem>
#include <string>
#include <variant>

#include "base/Result.h"
#include "scene/Mesh.h"

namespace specula::scene {

// Which mesh of the file: by index, by name, or (monostate) the file's only mesh.
using GltfMeshSelector = std::variant<std::monostate, std::size_t, std::string>;

// The triangle primitives of the selected mesh, concatenated into one mesh named `meshName`, in the
// mesh's own space (node transforms are ignored; the scene places the object). Primitives without
// normals get flat normals, as the glTF spec asks; uv is TEXCOORD_0 or (0, 0). Images are never
// decoded. External buffers must be files inside the asset's folder; data: URIs are fine.
// Fails with a message naming the file and the problem for unreadable, malformed, hostile or oversized
// input: bad GLB framing, accessors outside their buffers, wrong component types, out-of-range indices,
// non-finite values, non-triangle primitives, more than kMaxVerticesPerScene vertices.
Result<Mesh> importGltf(const std::filesystem::path& file, const GltfMeshSelector& which, std::string meshName);

}  // namespace specula::scene
