#include "scene/Environment.h"

#include "scene/AssetFiles.h"
#include "scene/Scene.h"

namespace specula::scene {

std::optional<Environment> namedEnvironment(std::string_view name) {
  if (name == "sky") return Environment{EnvironmentKind::Sky, std::nullopt};
  if (name == "none") return Environment{EnvironmentKind::Colour, std::nullopt};
  return std::nullopt;
}

Status useEnvironmentImage(Scene& scene, const std::filesystem::path& file) {
  Result<std::string> bytes = readBoundedFile(file, kMaxAssetFileBytes);
  if (!bytes) return Error{bytes.error()};
  Result<Texture> texture = decodeTexture(*bytes, file.filename().string());
  if (!texture) return Error{texture.error()};
  std::size_t texels = texture->texelCount();
  for (const Texture& other : scene.textures) texels += other.texelCount();
  if (texels > kMaxTexelsPerScene)
    return Error{file.string() + " makes the scene's textures hold more than " + std::to_string(kMaxTexelsPerScene) +
                 " texels; use a smaller image"};
  texture->wrapU = TextureWrap::Repeat;
  texture->wrapV = TextureWrap::ClampToEdge;
  scene.textures.push_back(std::move(texture).value());
  scene.environment = {EnvironmentKind::Image, static_cast<std::uint32_t>(scene.textures.size() - 1)};
  return {};
}

Status chooseEnvironment(Scene& scene, const std::string& choice) {
  if (const auto named = namedEnvironment(choice)) scene.environment = *named;
  else if (Status used = useEnvironmentImage(scene, choice); !used)
    return Error{"'" + choice + "' is neither sky, none nor an image this build reads: " + used.error()};
  return {};
}

}  // namespace specula::scene
