#include "scene/gltf/GltfMeshes.h"

#include <cmath>
#include <optional>
#include <variant>

#include "scene/MeshNormals.h"
#include "scene/Deformation.h"
#include "scene/Primitives.h"
#include "scene/SceneChecks.h"
#include "scene/gltf/GltfAccessors.h"

namespace specula::scene::gltf {

namespace {

// How far a vertex's joint weights may sum from 1: eight weights stored as bytes round by 0.5/255 each.
constexpr float kJointWeightSumTolerance = 0.016f;

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

  // Joint influences, in pairs: JOINTS_0 with WEIGHTS_0, then JOINTS_1 with WEIGHTS_1.
  for (int set = 0; set < 2; ++set) {
    const std::string jointsName = "JOINTS_" + std::to_string(set), weightsName = "WEIGHTS_" + std::to_string(set);
    const std::optional<int> jointsAt = attribute(primitive, jointsName), weightsAt = attribute(primitive, weightsName);
    if (!jointsAt && !weightsAt) break;
    if (!jointsAt || !weightsAt)
      return Error{name + " has " + (jointsAt ? jointsName : weightsName) + " without " +
                   (jointsAt ? weightsName : jointsName) + "; a vertex needs both to follow its joints"};
    Result<Accessor> joints =
        checkedAccessor(model, *jointsAt, jointsName + " of " + name, TINYGLTF_TYPE_VEC4,
                        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                        kMaxVerticesPerScene, IntegerComponents::Indices);
    if (!joints) return Error{joints.error()};
    Result<Accessor> weights = checkedAccessor(
        model, *weightsAt, weightsName + " of " + name, TINYGLTF_TYPE_VEC4,
        {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, kMaxVerticesPerScene);
    if (!weights) return Error{weights.error()};
    for (const Accessor* accessor : {&joints.value(), &weights.value()})
      if (accessor->count != part.vertices.size())
        return Error{accessor->name + " has " + std::to_string(accessor->count) + " elements but POSITION has " +
                     std::to_string(part.vertices.size())};
    JointInfluences& influences = part.influences.emplace_back();
    influences.joints.resize(part.vertices.size());
    influences.weights.resize(part.vertices.size());
    for (std::size_t v = 0; v < part.vertices.size(); ++v)
      for (int i = 0; i < 4; ++i) {
        influences.joints[v][i] = joints->integer(v, static_cast<std::size_t>(i));
        const float w = weights->component(v, static_cast<std::size_t>(i));
        if (!(w >= 0.0f && w <= 1.0f))
          return Error{weights->name + ": element " + std::to_string(v) + " has a weight outside [0, 1]"};
        influences.weights[v][i] = w;
      }
  }
  // glTF asks for weights summing to 1; what storing them as bytes rounds is scaled away.
  for (std::size_t v = 0; v < part.vertices.size() && !part.influences.empty(); ++v) {
    float sum = 0.0f;
    for (const JointInfluences& set : part.influences) sum += glm::dot(set.weights[v], glm::vec4(1.0f));
    if (!(std::abs(sum - 1.0f) <= kJointWeightSumTolerance))
      return Error{name + ": vertex " + std::to_string(v) + "'s joint weights sum to " + std::to_string(sum) +
                   "; glTF asks for 1"};
    for (JointInfluences& set : part.influences) set.weights[v] /= sum;
  }

  if (primitive.targets.size() > kMaxMorphTargets)
    return Error{name + " has " + std::to_string(primitive.targets.size()) + " morph targets, more than the " +
                 std::to_string(kMaxMorphTargets) + " a mesh may have"};
  for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
    MorphTarget& target = part.morphTargets.emplace_back();
    for (const auto& [semantic, list] : {std::pair{"POSITION", &target.positions}, {"NORMAL", &target.normals}}) {
      const auto it = primitive.targets[t].find(semantic);
      if (it == primitive.targets[t].end()) continue;
      const std::string role = "morph target " + std::to_string(t) + " " + semantic + " of " + name;
      Result<Accessor> accessor =
          checkedAccessor(model, it->second, role, TINYGLTF_TYPE_VEC3, {kFloat}, kMaxVerticesPerScene);
      if (!accessor) return Error{accessor.error()};
      if (accessor->count != part.vertices.size())
        return Error{accessor->name + " has " + std::to_string(accessor->count) + " elements but POSITION has " +
                     std::to_string(part.vertices.size())};
      list->resize(accessor->count);
      for (std::size_t i = 0; i < accessor->count; ++i) {
        const glm::vec3 d{accessor->component(i, 0), accessor->component(i, 1), accessor->component(i, 2)};
        const float limit = kMaxMorphDisplacement;  // comparisons false for NaN too
        if (!(std::abs(d.x) <= limit && std::abs(d.y) <= limit && std::abs(d.z) <= limit))
          return Error{accessor->name + ": element " + std::to_string(i) + " is not finite or beyond ±1e9"};
        (*list)[i] = d;
      }
    }
    if (target.positions.empty()) target.positions.assign(part.vertices.size(), glm::vec3(0.0f));
  }

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
    const std::vector<std::uint32_t> corners = part.indices;
    makeFlatShaded(part);
    // Each corner has its own vertex now; its displacements and joints follow it (normals stay the rest faces').
    const auto perCorner = [&](auto& list) {
      std::remove_reference_t<decltype(list)> expanded(corners.size());
      for (std::size_t i = 0; i < corners.size(); ++i) expanded[i] = list[corners[i]];
      list = std::move(expanded);
    };
    for (MorphTarget& target : part.morphTargets) {
      perCorner(target.positions);
      target.normals.clear();
    }
    for (JointInfluences& set : part.influences) {
      perCorner(set.joints);
      perCorner(set.weights);
    }
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
    // One mesh alone has no skeleton to follow: its rest shape at the mesh's weights.
    bakeDeformation(part.value(), std::vector<float>(source.weights.begin(), source.weights.end()), {});
    primitives::append(mesh, part.value(), glm::mat4(1.0f));
  }
  if (mesh.indices.empty()) return Error{"mesh " + std::to_string(index) + " has no primitives"};
  return mesh;
}

}  // namespace specula::scene::gltf
