// A Wavefront OBJ file, by its bytes, as a JSON scene's mesh (importObj).
#include <cstddef>
#include <cstdint>

#include "ScratchFolder.h"
#include "scene/ObjImporter.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::fuzz::ScratchFolder folder;
  (void)specula::scene::importObj(folder.write("fuzz.obj", data, size), "mesh");
  return 0;
}
