#include "scene/gltf/GltfImages.h"

#include <algorithm>
#include <string_view>

namespace specula::scene::gltf {

bool decodeImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto& images = *static_cast<DecodedImages*>(user);
  if (!images.decode) return true;
  const std::string name = "image " + std::to_string(index) +
                           (image->uri.empty() || image->uri.starts_with("data:") ? "" : " (" + image->uri + ")");
  Result<Texture> texture =
      decodeTexture({reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(std::max(size, 0))}, name);
  if (!texture) {
    *err = texture.error();
    return false;
  }
  if ((images.texels += texture->texelCount()) > kMaxTexelsPerScene) {
    *err = name + ": the file's images hold more than " + std::to_string(kMaxTexelsPerScene) +
           " texels with their mip chains; use smaller images";
    return false;
  }
  images.textures.emplace(index, std::move(texture).value());
  return true;
}

}  // namespace specula::scene::gltf
