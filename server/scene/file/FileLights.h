#pragma once
// A scene file's "lights" entries: directional or point lights.
#include "scene/JsonNode.h"
#include "scene/Light.h"

namespace specula::scene::file {

// {"type": "directional", "direction"} or {"type": "point", "position"}, with "color" and "intensity".
Light readLight(const JsonNode& node);

}  // namespace specula::scene::file
