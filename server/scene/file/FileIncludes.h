#pragma once
// A scene file's "includes" entries: glTF files' scenes placed as groups.
#include <filesystem>

#include "scene/JsonNode.h"
#include "scene/Scene.h"
#include "scene/file/FileMaterials.h"
#include "scene/file/FileNames.h"

namespace specula::scene::file {

// {"name": "engine", "file": "engine.glb", "scene": N, "translation", "rotation", "scale"}: a glTF
// file's scene (its default, or "scene") as a group placed by the transform. Its objects are named
// "<name>/<object>", so animations and protocol overrides can move them one by one; its materials
// and textures come along; its cameras and lights do not (the scene file has its own).
void readInclude(const JsonNode& node, const std::filesystem::path& baseDir, Scene& scene, Names& names,
                 TextureFiles& textures);

}  // namespace specula::scene::file
