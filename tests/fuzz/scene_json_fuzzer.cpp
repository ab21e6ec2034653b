// Scene JSON as loadSceneFile parses it, in a folder holding the test scenes' meshes and textures (in assets/) and
// the included glTF files, so the references and includes of the seeds load real assets.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ScratchFolder.h"
#include "scene/SceneLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::fuzz::ScratchFolder assets{
      {"scenes/good/assets", "assets"}, {"scenes/bad/assets", "assets"}, {"gltf", ""}};
  const std::string_view json(reinterpret_cast<const char*>(data), size);
  (void)specula::scene::parseScene(json, assets.path(), "fuzz.json");
  return 0;
}
