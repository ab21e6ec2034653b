#pragma once
// The names a scene file declares, so its entries can refer to each other by name.
#include "scene/NameIndex.h"

namespace specula::scene::file {

// Names of everything a scene file refers to by name.
struct Names {
  NameIndex meshes{"mesh"};
  NameIndex materials{"material"};
  NameIndex objects{"object"};
};

}  // namespace specula::scene::file
