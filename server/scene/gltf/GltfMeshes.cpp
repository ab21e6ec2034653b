#include "scene/gltf/GltfMeshes.h"

#include <cmath>
#include <optional>
#include <variant>

#include "scene/MeshNormals.h"
#include "scene/Primitives.h"
#include "scene/SceneChecks.h"
#include "scene/gltf/GltfAccessors.h"

namespace specula::scene::gltf {

namespace {

std::optional<int> attribute(const tinygltf::Primitive& primitive, const std::string& name) {
  const auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? std::nullopt : std::optional<int>(it->second);
}

std::string meshList(const tinygltf::Model& model) {
  std::string list;
  for (std::size_t i = 0; i < model.meshes.size() && i < 20; ++i)
    list +=
        (i ? ", " : "") + std::to_string(i) + (model.meshes[i].name.empty() ? "" : " \"" + model.meshes[i].name + "\"");
  return model.meshes.size() > 20 ? list + ", ..." : list;
}

}  // namespace

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

Result<Mesh> readMesh(const tinygltf::Model& model, std::size_t index, std::string name) {
  const tinygltf::Mesh& source = model.meshes[index];
  Mesh mesh;
  mesh.name = std::move(name);
  for (std::size_t p = 0; p < source.primitives.size(); ++p) {
    Result<Mesh> part = readPrimitive(model, source.primitives[p],
                                      "primitive " + std::to_string(p) + " of mesh " + std::to_string(index));
    if (!part) return Error{part.error()};
    if (mesh.vertices.size() + part->vertices.size() > kMaxVerticesPerScene)
      return Error{"mesh " + std::to_string(index) + " has more than " + std::to_string(kMaxVerticesPerScene) +
                   " vertices, the limit per scene"};
    primitives::append(mesh, part.value(), glm::mat4(1.0f));
  }
  if (mesh.indices.empty()) return Error{"mesh " + std::to_string(index) + " has no primitives"};
  return mesh;
}

}  // namespace specula::scene::gltf
