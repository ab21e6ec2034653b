#pragma once
// A loaded glTF asset's chosen scene built into a Specula scene.
#include <tiny_gltf.h>

#include <string>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/gltf/GltfImages.h"

namespace specula::scene::gltf {

// The scene `choice` picks, as importGltfScene describes it, named `name`; messages leave out the file.
Result<ImportedGltfScene> sceneFromModel(const tinygltf::Model& model, const DecodedImages& images,
                                         const GltfSceneChoice& choice, std::string name);

}  // namespace specula::scene::gltf
