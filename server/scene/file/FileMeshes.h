#pragma once
// A scene file's "meshes" entries: from an OBJ or glTF file, a primitive or a parametric surface.
#include <filesystem>

#include "scene/JsonNode.h"
#include "scene/Mesh.h"
#include "scene/NameIndex.h"

namespace specula::scene::file {

// A mesh entry, its name added to `meshes`: its source (files resolve inside `baseDir`), then long edges
// split when "max_edge" asks for it.
Mesh readMesh(const JsonNode& node, const std::filesystem::path& baseDir, NameIndex& meshes);

}  // namespace specula::scene::file
