#include "scene/GltfImporter.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "math/Bounds.h"
#include "math/Transform.h"
#include "scene/AssetFiles.h"
#include "scene/MeshTopology.h"
#include "scene/MeshNormals.h"
#include "scene/Primitives.h"
#include "scene/SceneChecks.h"
#include "scene/StrictJson.h"

namespace specula::scene {

namespace {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "GLB and glTF buffers are little-endian");

constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::uint32_t readU32(std::string_view bytes, std::size_t offset) {
  std::uint32_t value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

// The GLB's JSON chunk once the framing checks out; tinygltf 2.7 lets the BIN chunk run 8 bytes past the end.
Result<std::string_view> glbJsonChunk(std::string_view bytes) {
  const std::size_t size = bytes.size();
  if (size < 20) return Error{"truncated GLB: " + std::to_string(size) + " bytes, fewer than the 20-byte header"};
  if (const std::uint32_t version = readU32(bytes, 4); version != 2)
    return Error{"GLB container version " + std::to_string(version) + "; only glTF 2.0 is supported"};
  if (const std::uint32_t length = readU32(bytes, 8); length != size)
    return Error{"GLB header declares " + std::to_string(length) + " bytes but the file has " + std::to_string(size) +
                 " (truncated?)"};
  const std::uint64_t jsonLength = readU32(bytes, 12);
  if (readU32(bytes, 16) != kChunkJson) return Error{"the first GLB chunk is not the JSON chunk"};
  const std::uint64_t binStart = 20 + jsonLength;
  if (binStart > size) return Error{"the GLB JSON chunk runs past the end of the file"};
  if (binStart < size) {
    if (binStart + 8 > size) return Error{"the GLB BIN chunk header is truncated"};
    if (readU32(bytes, binStart + 4) != kChunkBin) return Error{"the second GLB chunk is not the BIN chunk"};
    if (binStart + 8 + readU32(bytes, binStart) > size) return Error{"the GLB BIN chunk runs past the end of the file"};
  }
  return bytes.substr(20, jsonLength);
}

// tinygltf copies the BIN chunk for every buffer without a URI, so declared sizes, not the file, bound its memory.
std::optional<std::string> bufferSizeProblem(const nlohmann::json& gltf) {
  if (!gltf.is_object() || !gltf.contains("buffers") || !gltf["buffers"].is_array()) return std::nullopt;
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < gltf["buffers"].size(); ++i) {
    const nlohmann::json& buffer = gltf["buffers"][i];
    const std::string where = "buffer " + std::to_string(i) + ": ";
    if (!buffer.is_object() || !buffer.contains("byteLength") || !buffer["byteLength"].is_number_unsigned())
      return where + "byteLength must be a positive integer";
    const std::uint64_t length = buffer["byteLength"].get<std::uint64_t>();
    if (length > kMaxAssetFileBytes || (total += length) > kMaxAssetFileBytes)
      return where + "buffers declare more than " + std::to_string(kMaxAssetFileBytes) + " bytes in all";
  }
  return std::nullopt;
}

// What tinygltf's file callbacks may read: files inside the folder, within one budget (URIs may repeat a file).
struct AssetFolder {
  fs::path folder;
  std::size_t bytesLeft = kMaxAssetFileBytes;
  std::string refusal;  // why a path was refused, to explain tinygltf's "file not found"
};

bool fileExists(const std::string& path, void* user) {
  auto& assets = *static_cast<AssetFolder*>(user);
  Result<fs::path> resolved = resolveInside(assets.folder, path);
  if (!resolved) {
    if (assets.refusal.empty()) assets.refusal = resolved.error();  // tinygltf retries with "./" prefixed
    return false;
  }
  std::error_code ec;
  return fs::exists(resolved.value(), ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto& assets = *static_cast<AssetFolder*>(user);
  Result<fs::path> resolved = resolveInside(assets.folder, path);
  Result<std::string> bytes = resolved ? readBoundedFile(resolved.value(), assets.bytesLeft) : Error{resolved.error()};
  if (!bytes) {
    *err = bytes.error();
    return false;
  }
  assets.bytesLeft -= bytes->size();
  out->assign(bytes->begin(), bytes->end());
  return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "the importer never writes files";
  return false;
}

// The file's images decoded (scene import), by glTF image index; a single mesh's import leaves them undecoded.
struct DecodedImages {
  bool decode = false;
  std::map<int, Texture> textures;
  std::size_t texels = 0;
  std::string unread;  // why an image could not be read, when tinygltf skipped one with a warning
};

// tinygltf's image callback, handed each image's encoded bytes (from a file, a data: URI or a buffer view).
bool decodeImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int, const unsigned char* bytes,
                 int size, void* user) {
  auto& images = *static_cast<DecodedImages*>(user);
  if (!images.decode) return true;
  const std::string name = "image " + std::to_string(index) + (image->uri.empty() || image->uri.starts_with("data:") ? "" : " (" + image->uri + ")");
  Result<Texture> texture = decodeTexture({reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(std::max(size, 0))}, name);
  if (!texture) {
    *err = texture.error();
    return false;
  }
  if ((images.texels += texture->texelCount()) > kMaxTexelsPerScene) {
    *err = name + ": the file's images hold more than " + std::to_string(kMaxTexelsPerScene) + " texels with their mip chains; use smaller images";
    return false;
  }
  images.textures.emplace(index, std::move(texture).value());
  return true;
}

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    default:
      return 4;
  }
}

std::string componentTypeName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return std::to_string(componentType);
  }
}

std::size_t componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    default:
      return 4;
  }
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    default:
      return "type " + std::to_string(type);
  }
}

// An accessor whose every element has been checked to lie inside its buffer view and buffer.
struct Accessor {
  std::string name;  // "accessor 3 (NORMAL of primitive 0)", for messages
  const unsigned char* first = nullptr;
  std::size_t count = 0;
  std::size_t stride = 0;
  int componentType = 0;

  // Component c of element i as a float; integer components count as normalized.
  float component(std::size_t i, std::size_t c) const {
    const unsigned char* at = first + i * stride + c * componentSize(componentType);
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return static_cast<float>(at[0]) / 255.0f;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return static_cast<float>(load<std::uint16_t>(at)) / 65535.0f;
      default:
        return load<float>(at);
    }
  }

  std::uint32_t index(std::size_t i) const {
    const unsigned char* at = first + i * stride;
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return at[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return load<std::uint16_t>(at);
      default:
        return load<std::uint32_t>(at);
    }
  }

  template <class T>
  static T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof value);  // glTF only aligns within buffer views, not in memory
    return value;
  }
};

Result<Accessor> checkedAccessor(const tinygltf::Model& model, int index, const std::string& role, int type,
                                 std::initializer_list<int> componentTypes, std::size_t maxCount) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    return Error{role + " refers to accessor " + std::to_string(index) + ", but the file has " +
                 std::to_string(model.accessors.size())};
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  Accessor checked;
  checked.name = "accessor " + std::to_string(index) + " (" + role + ")";
  const std::string where = checked.name + ": ";
  if (accessor.sparse.isSparse) return Error{where + "sparse accessors are not supported"};
  if (accessor.type != type)
    return Error{where + "has " + typeName(accessor.type) + " elements, expected " + typeName(type)};
  if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) == componentTypes.end()) {
    std::string allowed;
    for (int t : componentTypes) allowed += (allowed.empty() ? "" : ", ") + componentTypeName(t);
    return Error{where + "component type " + componentTypeName(accessor.componentType) +
                 " is not allowed here (allowed: " + allowed + ")"};
  }
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && type != TINYGLTF_TYPE_SCALAR && !accessor.normalized)
    return Error{where + "integer attributes must be normalized (KHR_mesh_quantization is not supported)"};
  if (accessor.count == 0) return Error{where + "is empty"};
  if (accessor.count > maxCount)
    return Error{where + "has " + std::to_string(accessor.count) + " elements, more than the limit of " +
                 std::to_string(maxCount)};
  if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
    return Error{where + "refers to buffer view " + std::to_string(accessor.bufferView) + ", but the file has " +
                 std::to_string(model.bufferViews.size()) + " (accessors without one are not supported)"};
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const std::string viewName = "buffer view " + std::to_string(accessor.bufferView);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    return Error{where + viewName + " refers to buffer " + std::to_string(view.buffer) + ", but the file has " +
                 std::to_string(model.buffers.size())};
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength)
    return Error{where + viewName + " (" + std::to_string(view.byteLength) + " bytes at offset " +
                 std::to_string(view.byteOffset) + ") lies outside buffer " + std::to_string(view.buffer) + " (" +
                 std::to_string(buffer.size()) + " bytes)"};
  const std::size_t elementSize = componentSize(accessor.componentType) * componentCount(type);
  checked.stride = view.byteStride != 0 ? view.byteStride : elementSize;
  if (checked.stride < elementSize)
    return Error{where + viewName + " has a byte stride of " + std::to_string(checked.stride) + ", less than the " +
                 std::to_string(elementSize) + "-byte element"};
  // Written as subtractions and a division so that no hostile count, stride or offset can overflow.
  if (accessor.byteOffset > view.byteLength || elementSize > view.byteLength - accessor.byteOffset ||
      accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / checked.stride)
    return Error{where + std::to_string(accessor.count) + " elements of " + std::to_string(elementSize) +
                 " bytes (stride " + std::to_string(checked.stride) + ", offset " +
                 std::to_string(accessor.byteOffset) + ") overrun " + viewName + " (" +
                 std::to_string(view.byteLength) + " bytes)"};
  checked.first = buffer.data() + view.byteOffset + accessor.byteOffset;
  checked.count = accessor.count;
  checked.componentType = accessor.componentType;
  return checked;
}

std::optional<int> attribute(const tinygltf::Primitive& primitive, const std::string& name) {
  const auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? std::nullopt : std::optional<int>(it->second);
}

Result<Mesh> readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           const std::string& name) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES)
    return Error{name + " has mode " + std::to_string(primitive.mode) + "; only triangle lists (mode 4) are supported"};
  if (!attribute(primitive, "POSITION")) return Error{name + " has no POSITION attribute"};
  Mesh part;
  // Reads one attribute, if present, into every vertex through `store`; POSITION comes first and sizes the mesh.
  const auto readAttribute = [&](const std::string& semantic, int type, std::initializer_list<int> componentTypes,
                                 const auto& store) -> std::optional<std::string> {
    const std::optional<int> index = attribute(primitive, semantic);
    if (!index) return std::nullopt;
    Result<Accessor> accessor =
        checkedAccessor(model, *index, semantic + " of " + name, type, componentTypes, kMaxVerticesPerScene);
    if (!accessor) return accessor.error();
    if (part.vertices.empty()) part.vertices.resize(accessor->count);
    if (accessor->count != part.vertices.size())
      return accessor->name + " has " + std::to_string(accessor->count) + " elements but POSITION has " +
             std::to_string(part.vertices.size());
    for (std::size_t i = 0; i < accessor->count; ++i) {
      glm::vec3 v{0.0f};
      for (std::size_t c = 0; c < componentCount(type); ++c)
        v[static_cast<glm::length_t>(c)] = accessor->component(i, c);
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        return accessor->name + ": element " + std::to_string(i) + " is not finite";
      if (!store(part.vertices[i], v)) return accessor->name + ": element " + std::to_string(i) + " is a zero vector";
    }
    return std::nullopt;
  };
  const int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
  const auto setPosition = [](Vertex& vertex, const glm::vec3& v) {
    vertex.position = v;
    return true;
  };
  const auto setNormal = [](Vertex& vertex, const glm::vec3& v) {
    const float length = glm::length(v);
    if (length > 0.0f) vertex.normal = v / length;
    return length > 0.0f;
  };
  const auto setUv = [](Vertex& vertex, const glm::vec3& v) {
    vertex.uv = {v.x, v.y};
    return true;
  };
  if (auto problem = readAttribute("POSITION", TINYGLTF_TYPE_VEC3, {kFloat}, setPosition)) return Error{*problem};
  if (auto problem = readAttribute("NORMAL", TINYGLTF_TYPE_VEC3, {kFloat}, setNormal)) return Error{*problem};
  if (auto problem =
          readAttribute("TEXCOORD_0", TINYGLTF_TYPE_VEC2,
                        {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, setUv))
    return Error{*problem};

  if (primitive.indices >= 0) {
    Result<Accessor> indices =
        checkedAccessor(model, primitive.indices, "indices of " + name, TINYGLTF_TYPE_SCALAR,
                        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                        3 * kMaxTrianglesPerScene);
    if (!indices) return Error{indices.error()};
    if (indices->count % 3 != 0)
      return Error{indices->name + " has " + std::to_string(indices->count) + " indices, not a multiple of 3"};
    part.indices.resize(indices->count);
    for (std::size_t i = 0; i < indices->count; ++i) {
      part.indices[i] = indices->index(i);
      if (part.indices[i] >= part.vertices.size())
        return Error{indices->name + ": index " + std::to_string(i) + " is " + std::to_string(part.indices[i]) +
                     ", but POSITION has " + std::to_string(part.vertices.size()) + " vertices"};
    }
  } else {
    if (part.vertices.size() % 3 != 0)
      return Error{name + " has no indices and " + std::to_string(part.vertices.size()) +
                   " vertices, not a multiple of 3"};
    part.indices.resize(part.vertices.size());
    for (std::size_t i = 0; i < part.indices.size(); ++i) part.indices[i] = static_cast<std::uint32_t>(i);
  }
  if (!attribute(primitive, "NORMAL")) {
    if (part.indices.size() > kMaxVerticesPerScene)
      return Error{name + " has no normals and needs " + std::to_string(part.indices.size()) +
                   " vertices once flat-shaded, more than the limit of " + std::to_string(kMaxVerticesPerScene)};
    makeFlatShaded(part);
  }
  return part;
}

std::string meshList(const tinygltf::Model& model) {
  std::string list;
  for (std::size_t i = 0; i < model.meshes.size() && i < 20; ++i)
    list +=
        (i ? ", " : "") + std::to_string(i) + (model.meshes[i].name.empty() ? "" : " \"" + model.meshes[i].name + "\"");
  return model.meshes.size() > 20 ? list + ", ..." : list;
}

Result<std::size_t> selectMesh(const tinygltf::Model& model, const GltfMeshSelector& which) {
  if (model.meshes.empty()) return Error{"the file holds no meshes"};
  if (const auto* index = std::get_if<std::size_t>(&which)) {
    if (*index < model.meshes.size()) return *index;
    return Error{"there is no mesh " + std::to_string(*index) + " (meshes: " + meshList(model) + ")"};
  }
  if (const auto* name = std::get_if<std::string>(&which)) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i)
      if (model.meshes[i].name == *name) return i;
    return Error{"there is no mesh named \"" + *name + "\" (meshes: " + meshList(model) + ")"};
  }
  if (model.meshes.size() == 1) return std::size_t{0};
  return Error{"the file holds " + std::to_string(model.meshes.size()) + " meshes (" + meshList(model) +
               "); pick one by index or name"};
}

// The parsed, checked asset: GLB framing, JSON depth and declared buffer sizes first, then tinygltf
// with file access confined to `folder`.
Result<tinygltf::Model> loadModel(std::string_view bytes, const fs::path& folder, DecodedImages& images) {
  if (bytes.empty()) return Error{"empty file; expected glTF JSON or a GLB container"};
  const bool binary = bytes.starts_with("glTF");
  Result<std::string_view> json = binary ? glbJsonChunk(bytes) : Result<std::string_view>(bytes);
  if (!json) return Error{json.error()};
  // Parsed strictly first: tinygltf walks "extras" recursively, so nesting depth must be bounded before it runs.
  Result<nlohmann::json> document = parseStrictJson(json.value());
  if (!document) return Error{document.error()};
  if (auto problem = bufferSizeProblem(document.value())) return Error{*problem};

  AssetFolder assets{folder, kMaxAssetFileBytes, {}};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decodeImage, &images);
  loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &assets});
  tinygltf::Model model;
  std::string error, warning;
  try {
    // An empty base folder makes tinygltf hand URIs to the callbacks unchanged; they resolve them in `folder`.
    const auto size = static_cast<unsigned int>(binary ? bytes.size() : json->size());
    const bool loaded =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()), size, "")
               : loader.LoadASCIIFromString(&model, &error, &warning, json->data(), size, "");
    if (!loaded)
      return Error{"not a valid glTF 2.0 asset: " + oneLine(error) +
                   (assets.refusal.empty() ? "" : " (" + assets.refusal + ")")};
  } catch (const std::exception& e) {
    return Error{"cannot be parsed: " + std::string(e.what())};
  }
  images.unread = assets.refusal.empty() ? oneLine(warning) : assets.refusal;
  return model;
}

// Every triangle primitive of mesh `index`, concatenated, in the mesh's own space.
Result<Mesh> readMesh(const tinygltf::Model& model, std::size_t index, std::string name) {
  const tinygltf::Mesh& source = model.meshes[index];
  Mesh mesh;
  mesh.name = std::move(name);
  for (std::size_t p = 0; p < source.primitives.size(); ++p) {
    Result<Mesh> part =
        readPrimitive(model, source.primitives[p], "primitive " + std::to_string(p) + " of mesh " + std::to_string(index));
    if (!part) return Error{part.error()};
    if (mesh.vertices.size() + part->vertices.size() > kMaxVerticesPerScene)
      return Error{"mesh " + std::to_string(index) + " has more than " + std::to_string(kMaxVerticesPerScene) +
                   " vertices, the limit per scene"};
    primitives::append(mesh, part.value(), glm::mat4(1.0f));
  }
  if (mesh.indices.empty()) return Error{"mesh " + std::to_string(index) + " has no primitives"};
  return mesh;
}


// What a glTF material is here: base colour factor (glTF holds linear RGB) and, where it is metallic
// and smooth enough to be a mirror, its reflectivity. Textures are not read yet.
// A glTF sampler's wrap mode (GL's enum values).
TextureWrap wrapFrom(int mode) {
  if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::ClampToEdge;
  if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::MirroredRepeat;
  return TextureWrap::Repeat;
}

Result<Material> materialFrom(const tinygltf::Material& source, std::size_t index, const GltfMirrorRule& rule, bool& chrome) {
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
    material.reflectivity = static_cast<float>(forced ? 1.0 : metallic) * std::max({material.baseColor.x, material.baseColor.y, material.baseColor.z});
  material.unlit = source.extensions.count("KHR_materials_unlit") > 0;
  return material;
}

// A node's own transform: its matrix, or translation · rotation · scale.
Result<glm::dmat4> nodeMatrix(const tinygltf::Node& node, std::size_t index) {
  const std::string where = "node " + std::to_string(index) + ": ";
  const auto finite = [](const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  };
  if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale))
    return Error{where + "its transform is not finite"};
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) return Error{where + "matrix must have 16 numbers"};
    glm::dmat4 m;
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row) m[column][row] = node.matrix[static_cast<std::size_t>(4 * column + row)];  // column-major
    return m;
  }
  glm::dmat4 m(1.0);
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) return Error{where + "translation must have 3 numbers"};
    m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) return Error{where + "rotation must be a quaternion of 4 numbers (x, y, z, w)"};
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (glm::length(q) < 1e-6) return Error{where + "rotation is a zero quaternion"};
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) return Error{where + "scale must have 3 numbers"};
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

// The light a node carries through KHR_lights_punctual, if any.
std::optional<int> nodeLight(const tinygltf::Node& node) {
  const auto extension = node.extensions.find("KHR_lights_punctual");
  if (extension == node.extensions.end() || !extension->second.IsObject() || !extension->second.Has("light")) return std::nullopt;
  const tinygltf::Value& light = extension->second.Get("light");
  return light.IsInt() ? std::optional<int>(light.GetNumberAsInt()) : std::nullopt;
}

// A view of the scene's bounds from the front, above and to the right, the whole box in a 45° frame.
math::Camera framingCamera(const Scene& scene) {
  math::Bounds bounds;
  for (const SceneObject& object : scene.objects)
    for (const Vertex& v : scene.meshes[object.mesh].vertices) bounds.add(v.position);
  const glm::vec3 centre = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  math::Camera camera;
  camera.fovYDegrees = 45.0f;
  camera.target = centre;
  camera.eye = centre + radius / std::sin(glm::radians(0.5f * camera.fovYDegrees)) * glm::normalize(glm::vec3(0.5f, 0.4f, 1.0f));
  return camera;
}

Result<ImportedGltfScene> sceneFromModel(const tinygltf::Model& model, const DecodedImages& decoded, const GltfSceneChoice& choice,
                                         std::string name) {
  ImportedGltfScene imported;
  Scene& scene = imported.scene;
  scene.name = std::move(name);
  scene.background = {0.05f, 0.06f, 0.08f};
  if (model.scenes.empty()) return Error{"the file holds no scene (\"scenes\" is empty), so nothing is placed to draw"};
  const std::size_t chosen = choice.scene ? *choice.scene : model.defaultScene >= 0 ? static_cast<std::size_t>(model.defaultScene) : 0;
  if (chosen >= model.scenes.size())
    return Error{"there is no scene " + std::to_string(chosen) + " (the file has " + std::to_string(model.scenes.size()) +
                 "; pick one of 0.." + std::to_string(model.scenes.size() - 1) + " with --gltf-scene, or \"scene\" in an include)"};

  // Base colour textures: glTF textures pair an image with a sampler; one scene texture per pair used.
  std::map<std::tuple<int, TextureWrap, TextureWrap>, std::uint32_t> textures;
  const auto textureOf = [&](const tinygltf::TextureInfo& info, std::size_t material) -> Result<std::optional<std::uint32_t>> {
    if (info.index < 0) return std::optional<std::uint32_t>();
    const std::string where = "material " + std::to_string(material) + ": baseColorTexture ";
    if (static_cast<std::size_t>(info.index) >= model.textures.size())
      return Error{where + "refers to texture " + std::to_string(info.index) + ", but the file has " + std::to_string(model.textures.size())};
    if (info.texCoord != 0) {
      imported.notes.push_back(where + "reads TEXCOORD_" + std::to_string(info.texCoord) + "; only TEXCOORD_0 is read, so it is left out");
      return std::optional<std::uint32_t>();
    }
    if (info.extensions.count("KHR_texture_transform") > 0)
      imported.notes.push_back(where + "has a KHR_texture_transform, which is not applied");
    const tinygltf::Texture& texture = model.textures[static_cast<std::size_t>(info.index)];
    const auto image = decoded.textures.find(texture.source);
    if (image == decoded.textures.end())
      return Error{where + "(texture " + std::to_string(info.index) + "): its image " + std::to_string(texture.source) +
                   " was not read (" + (decoded.unread.empty() ? "extensions such as KHR_texture_basisu are not read" : decoded.unread) + ")"};
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
    if (texture.sampler >= 0) {
      if (static_cast<std::size_t>(texture.sampler) >= model.samplers.size())
        return Error{where + "(texture " + std::to_string(info.index) + ") refers to sampler " + std::to_string(texture.sampler) +
                     ", but the file has " + std::to_string(model.samplers.size())};
      const tinygltf::Sampler& sampler = model.samplers[static_cast<std::size_t>(texture.sampler)];
      wrapU = wrapFrom(sampler.wrapS);
      wrapV = wrapFrom(sampler.wrapT);
    }
    const auto key = std::make_tuple(texture.source, wrapU, wrapV);
    if (const auto found = textures.find(key); found != textures.end()) return std::optional<std::uint32_t>(found->second);
    Texture copy = image->second;
    copy.wrapU = wrapU;
    copy.wrapV = wrapV;
    scene.textures.push_back(std::move(copy));
    return std::optional<std::uint32_t>(textures[key] = static_cast<std::uint32_t>(scene.textures.size() - 1));
  };

  // A rule naming a material the file lacks is a typo that would silently change nothing.
  for (const auto& [named, mirror] : choice.mirrors.materials)
    if (std::none_of(model.materials.begin(), model.materials.end(), [&](const tinygltf::Material& m) { return m.name == named; })) {
      std::string known;
      for (const tinygltf::Material& m : model.materials) known += (known.empty() ? "" : ", ") + ("\"" + m.name + "\"");
      return Error{"the mirror rule names material \"" + named + "\", which the file does not have (it has " +
                   (known.empty() ? std::string("none") : known) + ")"};
    }

  // Materials as primitives use them; -1 (none) gets glTF's default, a light grey here.
  std::map<int, std::pair<std::uint32_t, bool>> materials;  // glTF index -> scene index, chrome
  const auto materialOf = [&](int index) -> Result<std::pair<std::uint32_t, bool>> {
    if (const auto found = materials.find(index); found != materials.end()) return found->second;
    if (index >= static_cast<int>(model.materials.size()))
      return Error{"a primitive refers to material " + std::to_string(index) + ", but the file has " +
                   std::to_string(model.materials.size())};
    bool chrome = false;
    Material material;
    if (index < 0) {
      material.name = "default";
    } else {
      const tinygltf::Material& source = model.materials[static_cast<std::size_t>(index)];
      Result<Material> converted = materialFrom(source, static_cast<std::size_t>(index), choice.mirrors, chrome);
      if (!converted) return Error{converted.error()};
      material = std::move(converted.value());
      Result<std::optional<std::uint32_t>> texture = textureOf(source.pbrMetallicRoughness.baseColorTexture, static_cast<std::size_t>(index));
      if (!texture) return Error{texture.error()};
      material.texture = *texture;
    }
    scene.materials.push_back(std::move(material));
    return materials[index] = {static_cast<std::uint32_t>(scene.materials.size() - 1), chrome};
  };

  struct Pending {
    int node;
    glm::dmat4 parent;
  };
  std::vector<Pending> pending;
  for (auto it = model.scenes[chosen].nodes.rbegin(); it != model.scenes[chosen].nodes.rend(); ++it) pending.push_back({*it, glm::dmat4(1.0)});
  std::vector<bool> reached(model.nodes.size(), false);
  std::vector<std::pair<int, glm::dmat4>> cameras;  // camera index, placement, in the order first met
  std::vector<std::pair<int, glm::dmat4>> lights;
  std::size_t vertices = 0;
  std::set<std::string> names;
  while (!pending.empty()) {
    const Pending next = pending.back();
    pending.pop_back();
    if (next.node < 0 || static_cast<std::size_t>(next.node) >= model.nodes.size())
      return Error{"scene " + std::to_string(chosen) + " refers to node " + std::to_string(next.node) + ", but the file has " +
                   std::to_string(model.nodes.size())};
    const auto index = static_cast<std::size_t>(next.node);
    if (reached[index])
      return Error{"node " + std::to_string(index) + " is reached twice: the node tree has a cycle or a node with two parents"};
    reached[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    Result<glm::dmat4> local = nodeMatrix(node, index);
    if (!local) return Error{local.error()};
    const glm::dmat4 world = next.parent * local.value();
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) pending.push_back({*child, world});
    if (node.camera >= 0) cameras.push_back({node.camera, world});
    if (const auto light = nodeLight(node)) lights.push_back({*light, world});
    if (node.mesh < 0) continue;
    if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
      return Error{"node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) + ", but the file has " +
                   std::to_string(model.meshes.size())};
    const double determinant = glm::determinant(glm::dmat3(world));
    if (!(std::abs(determinant) > 1e-18)) {
      imported.notes.push_back("node " + std::to_string(index) + " has a singular transform (a zero scale): not drawn");
      continue;
    }
    const tinygltf::Mesh& source = model.meshes[static_cast<std::size_t>(node.mesh)];
    const std::string base = node.name.empty() ? "node " + std::to_string(index) : node.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      Result<Mesh> part = readPrimitive(model, source.primitives[p],
                                        "primitive " + std::to_string(p) + " of mesh " + std::to_string(node.mesh));
      if (!part) return Error{part.error()};
      if ((vertices += part->vertices.size()) > kMaxVerticesPerScene)
        return Error{"the scene has more than " + std::to_string(kMaxVerticesPerScene) + " vertices, the limit per scene"};
      // Placed in world space once (objects keep the identity): any matrix glTF allows, shear included.
      const glm::mat4 toWorld(world);
      const glm::mat3 normals = math::normalMatrix(toWorld);
      for (Vertex& v : part->vertices) {
        v.position = glm::vec3(toWorld * glm::vec4(v.position, 1.0f));
        v.normal = glm::normalize(normals * v.normal);
      }
      if (determinant < 0.0)  // a mirroring transform turns the winding; glTF keeps fronts where normals point
        for (std::size_t t = 0; t < part->indices.size(); t += 3) std::swap(part->indices[t + 1], part->indices[t + 2]);
      std::string objectName = source.primitives.size() > 1 ? base + " #" + std::to_string(p) : base;
      for (int copy = 2; names.count(objectName) > 0; ++copy) objectName = base + " (" + std::to_string(copy) + ")";
      names.insert(objectName);
      part->name = objectName;
      Result<std::pair<std::uint32_t, bool>> material = materialOf(source.primitives[p].material);
      if (!material) return Error{material.error()};
      const bool closed = topology::isWatertight(part.value());
      scene.meshes.push_back(std::move(part.value()));
      SceneObject object;
      object.name = objectName;
      object.mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
      object.material = material->first;
      if (material->second && closed) {
        object.mirror = MirrorInfo{};
        object.mirror->curvature = MirrorCurvature::Mixed;
      } else if (material->second) {
        scene.materials[material->first].reflectivity = 0.0f;
        imported.notes.push_back("'" + objectName + "' has a mirror material but an open mesh (a mirror needs a closed one): drawn in its colour");
      }
      scene.objects.push_back(std::move(object));
    }
  }
  if (scene.objects.empty()) return Error{"scene " + std::to_string(chosen) + " draws no mesh"};

  // The camera: the one asked for, or the first met, or a view framing everything.
  if (choice.camera && *choice.camera >= model.cameras.size())
    return Error{"there is no camera " + std::to_string(*choice.camera) + " (the file has " + std::to_string(model.cameras.size()) + ")"};
  const auto placed = std::find_if(cameras.begin(), cameras.end(), [&](const auto& c) {
    return !choice.camera || static_cast<std::size_t>(c.first) == *choice.camera;
  });
  scene.camera = framingCamera(scene);
  if (placed == cameras.end()) {
    if (choice.camera) return Error{"camera " + std::to_string(*choice.camera) + " is on no node of scene " + std::to_string(chosen)};
  } else if (placed->first < 0 || static_cast<std::size_t>(placed->first) >= model.cameras.size()) {
    return Error{"a node refers to camera " + std::to_string(placed->first) + ", but the file has " + std::to_string(model.cameras.size())};
  } else if (model.cameras[static_cast<std::size_t>(placed->first)].type != "perspective") {
    imported.notes.push_back("camera " + std::to_string(placed->first) + " is not perspective: the view frames the scene instead");
  } else {
    const glm::mat4 world(placed->second);
    const double yfov = model.cameras[static_cast<std::size_t>(placed->first)].perspective.yfov;
    math::Camera camera;
    camera.eye = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    camera.target = camera.eye + glm::normalize(glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)));  // glTF cameras look down -z
    camera.up = glm::normalize(glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)));
    camera.fovYDegrees = static_cast<float>(glm::degrees(yfov));
    if (auto problem = math::cameraProblem(camera)) return Error{"camera " + std::to_string(placed->first) + ": " + *problem};
    scene.camera = camera;
  }

  // KHR_lights_punctual: directions and positions from their nodes, intensities relative to the
  // brightest (glTF's lux and candela have no meaning for a one-bounce shading without falloff).
  double brightest = 0.0;
  for (const auto& [index, world] : lights) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size())
      return Error{"a node refers to light " + std::to_string(index) + ", but the file has " + std::to_string(model.lights.size())};
    const double intensity = model.lights[static_cast<std::size_t>(index)].intensity;
    if (!std::isfinite(intensity) || intensity < 0.0) return Error{"light " + std::to_string(index) + ": intensity must be finite and >= 0"};
    brightest = std::max(brightest, intensity);
  }
  for (const auto& [index, world] : lights) {
    const tinygltf::Light& source = model.lights[static_cast<std::size_t>(index)];
    if (scene.lights.size() == kMaxLights) {
      imported.notes.push_back("more than " + std::to_string(kMaxLights) + " lights: the rest are left out");
      break;
    }
    Light light;
    const glm::mat4 toWorld(world);
    if (source.type == "directional") {
      light.kind = Light::Kind::Directional;
      light.vector = glm::normalize(glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)));  // it shines down -z
    } else {
      if (source.type == "spot") imported.notes.push_back("light " + std::to_string(index) + " is a spot light: drawn as a point light");
      light.kind = Light::Kind::Point;
      light.vector = glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    if (source.color.size() == 3 && std::all_of(source.color.begin(), source.color.end(), [](double c) { return std::isfinite(c) && c >= 0.0; }))
      light.color = glm::vec3(source.color[0], source.color[1], source.color[2]);
    light.intensity = brightest > 0.0 ? static_cast<float>(source.intensity / brightest) : 0.0f;
    scene.lights.push_back(light);
  }
  if (scene.lights.empty()) {
    Light sun;
    sun.vector = glm::normalize(glm::vec3(0.4f, 1.0f, 0.6f));
    scene.lights.push_back(sun);
  }
  if (auto problem = sceneProblem(scene)) return Error{*problem};
  return imported;
}

}  // namespace

Result<Mesh> importGltf(const fs::path& file, const GltfMeshSelector& which, std::string meshName) {
  Result<std::string> bytes = readBoundedFile(file, kMaxAssetFileBytes);
  if (!bytes) return Error{bytes.error()};
  DecodedImages images;  // a mesh for a JSON scene draws in the scene's materials: its images are not read
  Result<tinygltf::Model> model = loadModel(bytes.value(), file.parent_path(), images);
  if (!model) return Error{file.string() + ": " + model.error()};
  Result<std::size_t> chosen = selectMesh(model.value(), which);
  if (!chosen) return Error{file.string() + ": " + chosen.error()};
  Result<Mesh> mesh = readMesh(model.value(), chosen.value(), std::move(meshName));
  if (!mesh) return Error{file.string() + ": " + mesh.error()};
  return mesh;
}

Result<ImportedGltfScene> importGltfScene(const fs::path& file, const GltfSceneChoice& choice) {
  Result<std::string> bytes = readBoundedFile(file, kMaxAssetFileBytes);
  if (!bytes) return Error{bytes.error()};
  DecodedImages images{true, {}, 0, {}};
  Result<tinygltf::Model> model = loadModel(bytes.value(), file.parent_path(), images);
  if (!model) return Error{file.string() + ": " + model.error()};
  Result<ImportedGltfScene> scene = sceneFromModel(model.value(), images, choice, file.stem().string());
  if (!scene) return Error{file.string() + ": " + scene.error()};
  return scene;
}

}  // namespace specula::scene
