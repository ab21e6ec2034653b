#include "scene/gltf/GltfMaterials.h"

#include <algorithm>
#include <cmath>

namespace specula::scene::gltf {

namespace {

// A glTF sampler's wrap mode (GL's enum values).
TextureWrap wrapFrom(int mode) {
  if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::ClampToEdge;
  if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::MirroredRepeat;
  return TextureWrap::Repeat;
}

// What a glTF material is here: base colour factor (glTF holds linear RGB) and, where the rule makes it
// a mirror, its reflectivity; its texture is read apart.
Result<Material> materialFrom(const tinygltf::Material& source, std::size_t index, const GltfMirrorRule& rule,
                              bool& chrome) {
  Material material;
  material.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
  const std::string where = "material " + std::to_string(index) + ": ";
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() != 4) return Error{where + "baseColorFactor must have 4 components"};
  for (int c = 0; c < 3; ++c) {
    const double value = pbr.baseColorFactor[static_cast<std::size_t>(c)];
    if (!std::isfinite(value) || value < 0.0 || value > 1.0) return Error{where + "baseColorFactor must lie in [0, 1]"};
    material.baseColor[c] = static_cast<float>(value);
  }
  const double metallic = pbr.metallicFactor, roughness = pbr.roughnessFactor;
  if (!std::isfinite(metallic) || !std::isfinite(roughness) || metallic < 0.0 || metallic > 1.0 || roughness < 0.0 ||
      roughness > 1.0)
    return Error{where + "metallicFactor and roughnessFactor must lie in [0, 1]"};
  const auto named = rule.materials.find(source.name);
  const bool forced = named != rule.materials.end();
  chrome = forced ? named->second : metallic >= rule.minMetallic && roughness <= rule.maxRoughness;
  // A metal reflects its base colour's share of the light; the brightest channel stands for it.
  if (chrome)
    material.reflectivity = static_cast<float>(forced ? 1.0 : metallic) *
                            std::max({material.baseColor.x, material.baseColor.y, material.baseColor.z});
  material.unlit = source.extensions.count("KHR_materials_unlit") > 0;
  return material;
}

}  // namespace

Status checkMirrorRuleNames(const tinygltf::Model& model, const GltfMirrorRule& rule) {
  for (const auto& entry : rule.materials) {
    const std::string& named = entry.first;  // not a structured binding: clang 14 cannot capture one in a lambda
    if (std::none_of(model.materials.begin(), model.materials.end(),
                     [&](const tinygltf::Material& m) { return m.name == named; })) {
      std::string known;
      for (const tinygltf::Material& m : model.materials) known += (known.empty() ? "" : ", ") + ("\"" + m.name + "\"");
      return Error{"the mirror rule names material \"" + named + "\", which the file does not have (it has " +
                   (known.empty() ? std::string("none") : known) + ")"};
    }
  }
  return {};
}

MaterialTable::MaterialTable(const tinygltf::Model& model, const DecodedImages& images, const GltfMirrorRule& rule,
                             Scene& scene, std::vector<std::string>& notes)
    : model_(model), images_(images), rule_(rule), scene_(scene), notes_(notes) {}

Result<SceneMaterial> MaterialTable::materialOf(int index) {
  if (const auto found = materials_.find(index); found != materials_.end()) return found->second;
  if (index >= static_cast<int>(model_.materials.size()))
    return Error{"a primitive refers to material " + std::to_string(index) + ", but the file has " +
                 std::to_string(model_.materials.size())};
  bool chrome = false;
  Material material;
  if (index < 0) {
    material.name = "default";
  } else {
    const tinygltf::Material& source = model_.materials[static_cast<std::size_t>(index)];
    Result<Material> converted = materialFrom(source, static_cast<std::size_t>(index), rule_, chrome);
    if (!converted) return Error{converted.error()};
    material = std::move(converted.value());
    Result<std::optional<std::uint32_t>> texture =
        textureOf(source.pbrMetallicRoughness.baseColorTexture, static_cast<std::size_t>(index));
    if (!texture) return Error{texture.error()};
    material.texture = *texture;
  }
  scene_.materials.push_back(std::move(material));
  return materials_[index] = {static_cast<std::uint32_t>(scene_.materials.size() - 1), chrome};
}

Result<std::optional<std::uint32_t>> MaterialTable::textureOf(const tinygltf::TextureInfo& info, std::size_t material) {
  if (info.index < 0) return std::optional<std::uint32_t>();
  const std::string where = "material " + std::to_string(material) + ": baseColorTexture ";
  if (static_cast<std::size_t>(info.index) >= model_.textures.size())
    return Error{where + "refers to texture " + std::to_string(info.index) + ", but the file has " +
                 std::to_string(model_.textures.size())};
  if (info.texCoord != 0) {
    notes_.push_back(where + "reads TEXCOORD_" + std::to_string(info.texCoord) +
                     "; only TEXCOORD_0 is read, so it is left out");
    return std::optional<std::uint32_t>();
  }
  if (info.extensions.count("KHR_texture_transform") > 0)
    notes_.push_back(where + "has a KHR_texture_transform, which is not applied");
  const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(info.index)];
  const auto image = images_.textures.find(texture.source);
  if (image == images_.textures.end())
    return Error{where + "(texture " + std::to_string(info.index) + "): its image " + std::to_string(texture.source) +
                 " was not read (" +
                 (images_.unread.empty() ? "extensions such as KHR_texture_basisu are not read" : images_.unread) +
                 ")"};
  TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
  if (texture.sampler >= 0) {
    if (static_cast<std::size_t>(texture.sampler) >= model_.samplers.size())
      return Error{where + "(texture " + std::to_string(info.index) + ") refers to sampler " +
                   std::to_string(texture.sampler) + ", but the file has " + std::to_string(model_.samplers.size())};
    const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
    wrapU = wrapFrom(sampler.wrapS);
    wrapV = wrapFrom(sampler.wrapT);
  }
  const auto key = std::make_tuple(texture.source, wrapU, wrapV);
  if (const auto found = textures_.find(key); found != textures_.end())
    return std::optional<std::uint32_t>(found->second);
  Texture copy = image->second;
  copy.wrapU = wrapU;
  copy.wrapV = wrapV;
  scene_.textures.push_back(std::move(copy));
  return std::optional<std::uint32_t>(textures_[key] = static_cast<std::uint32_t>(scene_.textures.size() - 1));
}

}  // namespace specula::scene::gltf
