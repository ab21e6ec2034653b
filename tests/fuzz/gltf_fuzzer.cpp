// A .gltf (JSON) or .glb (binary) file, by its bytes, as a JSON scene's mesh (importGltf) and as an
// included glTF scene with its textures and animations (importGltfScene, then posed at a few times),
// beside the test assets its URIs may name.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <variant>

#include "ScratchFolder.h"
#include "scene/GltfImporter.h"
#include "scene/ScenePose.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::fuzz::ScratchFolder assets{{"scenes/good/assets", ""}, {"gltf", ""}};
  const std::filesystem::path file = assets.write("fuzz.gltf", data, size);
  (void)specula::scene::importGltf(file, std::monostate{}, "mesh");
  const auto imported = specula::scene::importGltfScene(file);
  if (imported)  // a scene that imports must pose at any time: its animations are sampled here
    for (double seconds : {0.0, 0.37, 5.1, -2.0}) (void)specula::scene::ScenePose::at(imported->scene, seconds);
  return 0;
}
