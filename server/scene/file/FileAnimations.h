#pragma once
// A scene file's "animations" entries: spins, orbits and keyframed paths of objects or the camera.
#include "scene/Animation.h"
#include "scene/JsonNode.h"
#include "scene/Scene.h"
#include "scene/file/FileNames.h"

namespace specula::scene::file {

// An animation of the object `names` finds for its "target", or of the camera ("camera"); keyframes
// leave out what they do not set, which keeps its rest value in `scene`.
Animation readAnimation(const JsonNode& node, const Names& names, const Scene& scene);

}  // namespace specula::scene::file
