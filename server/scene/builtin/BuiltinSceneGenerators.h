#pragma once
// One generator per built-in scene, each in its own file; only BuiltinScenes.cpp calls them.
#include "scene/Scene.h"

namespace specula::scene::builtin {

Scene checkerSphereScene();
Scene meshSphereScene();
Scene cylinderScene();
Scene kitchenScene();
Scene ufoScene();
Scene antsScene();
Scene quadScene();
Scene teapotTableScene();
Scene beadsScene();
Scene utahTeapotScene();
Scene flagScene();

}  // namespace specula::scene::builtin
