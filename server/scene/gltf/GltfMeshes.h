#pragma once
// A glTF mesh's triangle primitives read into Specula meshes, every accessor and index checked.
#include <tiny_gltf.h>

#include <cstddef>
#include <string>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/Mesh.h"

namespace specula::scene::gltf {

// One triangle primitive as a mesh in its own space, named `name` in messages: POSITION, NORMAL (flat
// normals when absent, as the glTF spec asks) and TEXCOORD_0 (else (0, 0)), indexed or not.
Result<Mesh> readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name);

// The index of the mesh `which` picks; the message lists the file's meshes when it picks none.
Result<std::size_t> selectMesh(const tinygltf::Model& model, const GltfMeshSelector& which);

// Every triangle primitive of mesh `index`, concatenated, in the mesh's own space.
Result<Mesh> readMesh(const tinygltf::Model& model, std::size_t index, std::string name);

}  // namespace specula::scene::gltf
