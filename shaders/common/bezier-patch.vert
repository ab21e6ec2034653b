#version 430 core
// One GL patch per Bézier patch, of one vertex with no attributes: the tessellation stages read the
// patch's 16 control points from storage themselves (passes::GpuMeshes::drawPatches).

void main() {}
