#pragma once
// A scene file's "primitive" meshes: grid, sphere, box, cylinder, torus and lathe.
#include <string>

#include "scene/JsonNode.h"
#include "scene/Mesh.h"

namespace specula::scene::file {

// {"type": ..., and that type's sizes and segment counts}, built as a mesh named `name`.
Mesh readPrimitive(const JsonNode& node, std::string name);

}  // namespace specula::scene::file
