#pragma once
// Wavefront OBJ import (tinyobjloader) into one triangle mesh.
#include <filesystem>
#include <string>

#include "base/Result.h"
#include "scene/Mesh.h"

namespace specula::scene {

// Every face of every group in `file`, fan-triangulated, as one mesh named `meshName`. Vertices are
// shared where the OBJ shares a (position, uv, normal) triple; uv is (0, 0) where the file has none;
// when any face lacks normals, all are recomputed smooth. Materials (mtllib, usemtl) and tags are
// ignored. Fails with a message naming the file and the problem for unreadable, malformed or
// oversized input (out-of-range indices, non-finite numbers, more than kMaxVerticesPerScene vertices).
Result<Mesh> importObj(const std::filesystem::path& file, std::string meshName);

}  // namespace specula::scene
