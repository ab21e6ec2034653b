#pragma once
// The KHR_lights_punctual lights of an imported glTF scene, or a default light when it has none.
#include <tiny_gltf.h>

#include <vector>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/gltf/GltfNodes.h"

namespace specula::scene::gltf {

// Adds the lights met in the node tree (at most kMaxLights; spot lights become point lights, with a
// note), their intensities relative to the brightest; a default sun when there are none.
Status addLights(const tinygltf::Model& model, const std::vector<NodeAttachment>& lights, ImportedGltfScene& imported);

}  // namespace specula::scene::gltf
