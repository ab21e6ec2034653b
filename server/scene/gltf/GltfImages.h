#pragma once
// The images of a glTF file decoded into textures as tinygltf reads them (a scene import), or left
// undecoded (a single mesh's import).
#include <tiny_gltf.h>

#include <cstddef>
#include <map>
#include <string>

#include "scene/Texture.h"

namespace specula::scene::gltf {

// The file's images decoded (scene import), by glTF image index; a single mesh's import leaves them undecoded.
struct DecodedImages {
  bool decode = false;
  std::map<int, Texture> textures;
  std::size_t texels = 0;
  std::string unread;  // why an image could not be read, when tinygltf skipped one with a warning
};

// tinygltf's image callback, handed each image's encoded bytes (from a file, a data: URI or a buffer
// view); `user` is the DecodedImages to fill. Fails past kMaxTexelsPerScene texels in all.
bool decodeImage(tinygltf::Image* image, int index, std::string* err, std::string* warning, int requiredWidth,
                 int requiredHeight, const unsigned char* bytes, int size, void* user);

}  // namespace specula::scene::gltf
