// A .gltf (JSON) or .glb (binary) file, by its bytes, as a JSON scene's mesh (importGltf) and as an
// included glTF scene with its textures (importGltfScene), beside the test assets its URIs may name.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <variant>

#include "ScratchFolder.h"
#include "scene/GltfImporter.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::fuzz::ScratchFolder assets{{"scenes/good/assets", ""}, {"gltf", ""}};
  const std::filesystem::path file = assets.write("fuzz.gltf", data, size);
  (void)specula::scene::importGltf(file, std::monostate{}, "mesh");
  (void)specula::scene::importGltfScene(file);
  return 0;
}
