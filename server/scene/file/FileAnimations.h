#pragma once
// A scene file's "animations" entries: spins, orbits and keyframed paths of objects or the camera.
#include "scene/Animation.h"
#include "scene/JsonNode.h"
#include "scene/Scene.h"
#include "scene/file/FileNames.h"

namespace specula::scene::file {

// An animation of the object its "target" names (found in `names`) or of the camera ("camera"); what a
// path's key leaves out keeps its rest value in `scene`.
Animation readAnimation(const JsonNode& node, const Names& names, const Scene& scene);

}  // namespace specula::scene::file
