// A .gltf (JSON) or .glb (binary) file, by its bytes, as a JSON scene's mesh (importGltf) and as an
// included glTF scene with its textures, animations, morph targets and skins (importGltfScene, then posed
// at a few times and its deforming meshes deformed), beside the test assets its URIs may name.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <variant>

#include "ScratchFolder.h"
#include "scene/Deformation.h"
#include "scene/GltfImporter.h"
#include "scene/ScenePose.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::fuzz::ScratchFolder assets{{"scenes/good/assets", ""}, {"gltf", ""}};
  const std::filesystem::path file = assets.write("fuzz.gltf", data, size);
  (void)specula::scene::importGltf(file, std::monostate{}, "mesh");
  const auto imported = specula::scene::importGltfScene(file);
  if (!imported) return 0;
  // A scene that imports must pose at any time: its animations are sampled, its meshes deformed.
  const specula::scene::Scene& scene = imported->scene;
  for (double seconds : {0.0, 0.37, 5.1, -2.0}) {
    const auto pose = specula::scene::ScenePose::at(scene, seconds);
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (!pose.morphWeights[i].empty() || !pose.jointMatrices[i].empty())
        (void)specula::scene::deformedVertices(scene.meshes[scene.objects[i].mesh], pose.morphWeights[i],
                                               pose.jointMatrices[i]);
  }
  return 0;
}
