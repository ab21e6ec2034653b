#include "scene/gltf/GltfScene.h"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scene/Deformation.h"
#include "scene/SceneChecks.h"
#include "scene/gltf/GltfAnimations.h"
#include "scene/gltf/GltfCamera.h"
#include "scene/gltf/GltfLights.h"
#include "scene/gltf/GltfMaterials.h"
#include "scene/gltf/GltfNodes.h"
#include "scene/gltf/GltfObjects.h"
#include "scene/gltf/GltfSkins.h"

namespace specula::scene::gltf {

namespace {

// The scene asked for, else the file's default scene, else its first.
Result<std::size_t> chosenScene(const tinygltf::Model& model, const GltfSceneChoice& choice) {
  if (model.scenes.empty()) return Error{"the file holds no scene (\"scenes\" is empty), so nothing is placed to draw"};
  const std::size_t chosen = choice.scene              ? *choice.scene
                             : model.defaultScene >= 0 ? static_cast<std::size_t>(model.defaultScene)
                                                       : 0;
  if (chosen >= model.scenes.size())
    return Error{"there is no scene " + std::to_string(chosen) + " (the file has " +
                 std::to_string(model.scenes.size()) + "; pick one of 0.." + std::to_string(model.scenes.size() - 1) +
                 " with --gltf-scene, or \"scene\" in an include)"};
  return chosen;
}

// What the file holds that this build does not play or read, named once each so nothing is left out in silence.
void noteWhatIsNotRead(const tinygltf::Model& model, std::vector<std::string>& notes) {
  // Vertex attributes beyond those read (a second UV set, vertex colours, tangents), once each with how
  // many primitives have them; likewise morph target displacements of attributes other than these two.
  static const std::set<std::string, std::less<>> kAttributesRead = {"POSITION",  "NORMAL",   "TEXCOORD_0", "JOINTS_0",
                                                                     "WEIGHTS_0", "JOINTS_1", "WEIGHTS_1"};
  std::map<std::string, std::size_t> unread, unreadTargets;
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      for (const auto& [name, accessor] : primitive.attributes)
        if (!kAttributesRead.contains(name)) ++unread[name];
      std::set<std::string> displaced;
      for (const auto& target : primitive.targets)
        for (const auto& [name, accessor] : target)
          if (name != "POSITION" && name != "NORMAL") displaced.insert(name);
      for (const std::string& name : displaced) ++unreadTargets[name];
    }
  const auto primitives = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " primitive" : " primitives"); };
  for (const auto& [name, count] : unread)
    notes.push_back("vertex attribute " + name + " (on " + primitives(count) + ") is not read");
  for (const auto& [name, count] : unreadTargets)
    notes.push_back("morph target " + name + " displacements (on " + primitives(count) + ") are not read");
  // The extensions the importer reads; KHR_texture_transform and KHR_mesh_quantization are named where used.
  static const std::set<std::string, std::less<>> kRead = {"KHR_lights_punctual", "KHR_materials_unlit",
                                                           "KHR_texture_transform", "KHR_mesh_quantization"};
  for (const std::string& extension : model.extensionsUsed)
    if (!kRead.contains(extension))
      notes.push_back("extension " + extension + " is not read: what it adds is left out");
}

}  // namespace

Result<ImportedGltfScene> sceneFromModel(const tinygltf::Model& model, const DecodedImages& images,
                                         const GltfSceneChoice& choice, std::string name) {
  ImportedGltfScene imported;
  imported.scene.name = std::move(name);
  imported.scene.background = {0.05f, 0.06f, 0.08f};       // with --environment none
  imported.scene.environment.kind = EnvironmentKind::Sky;  // as glTF viewers light and reflect one by default
  Result<std::size_t> chosen = chosenScene(model, choice);
  if (!chosen) return Error{chosen.error()};
  if (Status named = checkMirrorRuleNames(model, choice.mirrors); !named) return Error{named.error()};
  noteWhatIsNotRead(model, imported.scene.notes);

  std::vector<VisitedNode> visited;  // parents before their children
  const Status walked = walkNodeTree(model, chosen.value(), [&](const VisitedNode& node) {
    visited.push_back(node);
    return Status{};
  });
  if (!walked) return Error{walked.error()};

  // Every node of the scene joins the rig; only the objects under a node some animation moves use it.
  NodeRig& rig = imported.scene.rig;
  std::vector<std::optional<std::uint32_t>> rigNode(model.nodes.size());
  for (const VisitedNode& node : visited) {
    rigNode[node.index] = static_cast<std::uint32_t>(rig.nodes.size());
    rig.nodes.push_back(node.rest);
    if (node.parent) rig.nodes.back().parent = rigNode[*node.parent];
  }
  Result<std::vector<NodeClip>> clips = readClips(model, choice.animation, rigNode, imported.scene.notes);
  if (!clips) return Error{clips.error()};
  rig.clips = std::move(clips).value();
  std::vector<bool> moved(rig.nodes.size(), false), morphing(rig.nodes.size(), false);
  for (const NodeClip& clip : rig.clips)
    for (const NodeChannel& channel : clip.channels)
      (channel.property == NodeProperty::Weights ? morphing : moved)[channel.node] = true;
  for (std::size_t i = 0; i < rig.nodes.size(); ++i)
    if (rig.nodes[i].parent && moved[*rig.nodes[i].parent]) moved[i] = true;
  NodeRig still;
  still.nodes = rig.nodes;
  const std::vector<glm::dmat4> restWorld = still.worldAt(0.0);  // scales clamped as animations draw them

  // Each skin a drawn mesh uses, read once; it poses the mesh every frame when anything animates.
  std::map<std::size_t, std::uint32_t> rigSkin;  // file skin → rig.skins
  const auto deformationOf = [&](std::uint32_t i) -> Result<NodeDeformation> {
    const tinygltf::Node& node = model.nodes[visited[i].index];
    NodeDeformation deformation;
    deformation.weightsAnimate = morphing[i];
    if (node.skin < 0 || node.mesh < 0) return deformation;
    if (static_cast<std::size_t>(node.skin) >= model.skins.size())
      return Error{"$.nodes[" + std::to_string(visited[i].index) + "].skin: refers to skin " +
                   std::to_string(node.skin) + ", but the file has " + std::to_string(model.skins.size())};
    const auto skin = static_cast<std::size_t>(node.skin);
    if (!rigSkin.contains(skin)) {
      Result<RigSkin> read = readSkin(model, skin, rigNode);
      if (!read) return Error{read.error()};
      rigSkin[skin] = static_cast<std::uint32_t>(rig.skins.size());
      rig.skins.push_back(std::move(read).value());
    }
    deformation.restJoints = skinMatrices(rig.skins[rigSkin[skin]], restWorld, i);
    if (rig.moves()) deformation.skin = rigSkin[skin];
    return deformation;
  };

  MaterialTable materials(model, images, choice.mirrors, imported.scene, imported.scene.notes);
  ObjectPlacer objects(model, materials, imported);
  std::vector<NodeAttachment> cameras, lights;  // in the order first met
  for (std::uint32_t i = 0; i < visited.size(); ++i) {
    const tinygltf::Node& node = model.nodes[visited[i].index];
    const std::optional<std::uint32_t> mover = moved[i] ? std::optional(i) : std::nullopt;
    if (node.camera >= 0) cameras.push_back({node.camera, visited[i].world, mover});
    if (const auto light = nodeLight(node)) {
      lights.push_back({*light, visited[i].world, mover});
      if (mover)
        imported.scene.notes.push_back("light " + std::to_string(*light) +
                                       " is on an animated node: it stays where the rest pose puts it");
    }
    Result<NodeDeformation> deformation = deformationOf(i);
    if (!deformation) return Error{deformation.error()};
    const bool deforms = deformation->weightsAnimate || deformation->skin;
    const std::optional<std::uint32_t> holder = mover || deforms ? std::optional(i) : std::nullopt;
    if (Status placed =
            objects.placeNodeMesh(visited[i].index, holder ? restWorld[i] : visited[i].world, holder, *deformation);
        !placed)
      return Error{placed.error()};
  }
  if (imported.scene.objects.empty()) return Error{"scene " + std::to_string(chosen.value()) + " draws no mesh"};
  if (!rig.moves()) rig = NodeRig{};  // a still scene keeps its meshes in world space and needs no rig

  if (Status placed = placeCamera(model, cameras, choice.camera, chosen.value(), imported); !placed)
    return Error{placed.error()};
  if (Status lit = addLights(model, lights, imported); !lit) return Error{lit.error()};
  if (auto problem = sceneProblem(imported.scene)) return Error{*problem};
  return imported;
}

}  // namespace specula::scene::gltf
