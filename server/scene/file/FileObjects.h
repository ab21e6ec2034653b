#pragma once
// A scene file's "objects" entries: a mesh drawn in a material, placed, maybe a mirror.
#include "scene/JsonNode.h"
#include "scene/SceneObject.h"
#include "scene/file/FileNames.h"

namespace specula::scene::file {

// An object, its name added to `names`; its mesh and material are found there by name.
SceneObject readObject(const JsonNode& node, Names& names);

}  // namespace specula::scene::file
