#include "scene/gltf/GltfObjects.h"

#include <cmath>
#include <utility>

#include "math/Transform.h"
#include "scene/MeshTopology.h"
#include "scene/Deformation.h"
#include "scene/SceneChecks.h"
#include "scene/gltf/GltfAnimations.h"
#include "scene/gltf/GltfMeshes.h"

namespace specula::scene::gltf {

namespace {

// Placed in world space once (objects keep the identity): any matrix glTF allows, shear included.
void moveToWorld(Mesh& part, const glm::dmat4& world) {
  const glm::mat4 toWorld(world);
  const glm::mat3 normals = math::normalMatrix(toWorld);
  for (Vertex& v : part.vertices) {
    v.position = glm::vec3(toWorld * glm::vec4(v.position, 1.0f));
    v.normal = glm::normalize(normals * v.normal);
  }
}

// A mirroring transform turns the winding; glTF keeps fronts where normals point.
void keepFrontsUnder(Mesh& part, const glm::dmat4& world) {
  if (glm::determinant(glm::dmat3(world)) < 0.0)
    for (std::size_t t = 0; t < part.indices.size(); t += 3) std::swap(part.indices[t + 1], part.indices[t + 2]);
}

}  // namespace

ObjectPlacer::ObjectPlacer(const tinygltf::Model& model, MaterialTable& materials, ImportedGltfScene& imported)
    : model_(model), materials_(materials), imported_(imported) {}

Status ObjectPlacer::placeNodeMesh(std::size_t index, const glm::dmat4& world, std::optional<std::uint32_t> rigNode,
                                   const NodeDeformation& deformation) {
  const tinygltf::Node& node = model_.nodes[index];
  if (node.mesh < 0) return {};
  if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
    return Error{"node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) +
                 ", but the file has " + std::to_string(model_.meshes.size())};
  if (!(std::abs(glm::determinant(glm::dmat3(world))) > 1e-18)) {
    imported_.scene.notes.push_back("node " + std::to_string(index) +
                                    " has a singular transform (a zero scale): not drawn");
    return {};
  }
  const tinygltf::Mesh& source = model_.meshes[static_cast<std::size_t>(node.mesh)];
  const std::string base = node.name.empty() ? "node " + std::to_string(index) : node.name;
  // The node's weights, else its mesh's, else zeros (glTF's defaults).
  const std::vector<double>& given = node.weights.empty() ? source.weights : node.weights;
  std::vector<float> weights(given.begin(), given.end());
  for (std::size_t p = 0; p < source.primitives.size(); ++p) {
    const std::string where = "$.meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(p) + "]";
    Result<Mesh> part = readPrimitive(model_, source.primitives[p],
                                      "primitive " + std::to_string(p) + " of mesh " + std::to_string(node.mesh));
    if (!part) return Error{part.error()};
    const std::size_t targets = source.primitives.front().targets.size();
    if (part->morphTargets.size() != targets)
      return Error{where + ".targets: " + std::to_string(part->morphTargets.size()) +
                   " morph targets, but primitive 0 has " + std::to_string(targets) +
                   " (every primitive of a mesh has as many)"};
    if (!given.empty() && given.size() != targets)
      return Error{"node " + std::to_string(index) + " or its mesh " + std::to_string(node.mesh) + " has " +
                   std::to_string(given.size()) + " weights for " + std::to_string(targets) + " morph targets"};
    weights.resize(targets, 0.0f);
    for (float w : weights)
      if (!(std::abs(w) <= kMaxKeyMagnitude))
        return Error{"node " + std::to_string(index) + ": a morph target weight is not finite or beyond ±1e9"};
    if ((vertices_ += part->vertices.size()) > kMaxVerticesPerScene)
      return Error{"the scene has more than " + std::to_string(kMaxVerticesPerScene) +
                   " vertices, the limit per scene"};
    const bool skinned = !deformation.restJoints.empty();
    if (skinned && part->influences.empty())
      return Error{"$.nodes[" + std::to_string(index) + "].skin: primitive " + std::to_string(p) + " of mesh " +
                   std::to_string(node.mesh) + " has no JOINTS_0 and WEIGHTS_0 to follow the skin's joints"};
    if (!skinned) part->influences.clear();  // a mesh without a skin is drawn as it rests
    if (!deformation.weightsAnimate) {
      part->vertices = deformedVertices(part.value(), weights, {});
      part->morphTargets.clear();
    }
    if (skinned && !deformation.skin) bakeDeformation(part.value(), {}, deformation.restJoints);
    if (!rigNode) moveToWorld(part.value(), world);
    keepFrontsUnder(part.value(), world);
    const auto object = static_cast<std::uint32_t>(imported_.scene.objects.size());
    if (rigNode) imported_.scene.rig.objects.push_back({object, *rigNode});
    part->name = uniqueName(source.primitives.size() > 1 ? base + " #" + std::to_string(p) : base, base);
    if (Status added = addObject(std::move(part.value()), source.primitives[p].material); !added) return added;
    const Mesh& added = imported_.scene.meshes.back();
    if (!added.morphTargets.empty()) imported_.scene.rig.morphed.push_back({object, *rigNode, weights});
    if (!added.influences.empty()) imported_.scene.rig.skinned.push_back({object, *deformation.skin, *rigNode});
  }
  return {};
}

// `wanted`, or else the first of "base (2)", "base (3)", ... no object has yet.
std::string ObjectPlacer::uniqueName(const std::string& wanted, const std::string& base) {
  std::string name = wanted;
  for (int copy = 2; names_.count(name) > 0; ++copy) name = base + " (" + std::to_string(copy) + ")";
  names_.insert(name);
  return name;
}

Status ObjectPlacer::addObject(Mesh part, int material) {
  Result<SceneMaterial> converted = materials_.materialOf(material);
  if (!converted) return Error{converted.error()};
  Scene& scene = imported_.scene;
  const bool closed = topology::isWatertight(part);
  SceneObject object;
  object.name = part.name;
  scene.meshes.push_back(std::move(part));
  object.mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  object.material = converted->index;
  if (converted->chrome) {
    object.mirror = MirrorInfo{};
    object.mirror->curvature = MirrorCurvature::Mixed;
    object.mirror->closed = closed;
    if (!closed)
      imported_.scene.notes.push_back("'" + object.name +
                                      "' is an open mesh: a two-sided mirror whose reflections are ray-cast (only a "
                                      "closed mesh can be searched)");
  }
  scene.objects.push_back(std::move(object));
  return {};
}

}  // namespace specula::scene::gltf
