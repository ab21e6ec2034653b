#include "scene/file/FileIncludes.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "base/Result.h"
#include "scene/AssetFiles.h"
#include "scene/GltfImporter.h"
#include "scene/file/FileMirrors.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

namespace fs = std::filesystem;

namespace {

// An included file's rig joins the scene's, its nodes and objects renumbered after those already there and
// its clips named "<group>/<clip>". Its camera does not: a scene file has its own.
void mergeRig(NodeRig included, std::uint32_t objectOffset, const std::string& group, NodeRig& rig) {
  const auto nodeOffset = static_cast<std::uint32_t>(rig.nodes.size());
  for (RigNode& node : included.nodes) {
    if (node.parent) *node.parent += nodeOffset;
    rig.nodes.push_back(std::move(node));
  }
  for (NodeClip& clip : included.clips) {
    for (NodeChannel& channel : clip.channels) channel.node += nodeOffset;
    clip.name = group + "/" + clip.name;
    rig.clips.push_back(std::move(clip));
  }
  for (const RiggedObject& rigged : included.objects)
    rig.objects.push_back({rigged.object + objectOffset, rigged.node + nodeOffset});
}

}  // namespace

void readInclude(const JsonNode& node, const fs::path& baseDir, Scene& scene, Names& names, TextureFiles& textures) {
  node.expectObject({"name", "file", "scene", "animation", "mirror_rule", "translation", "rotation", "scale"});
  const JsonNode nameNode = node.at("name");
  const std::string& group = nameNode.string();
  if (group.empty() || group.find('/') != std::string::npos)
    nameNode.fail("an include's name must be non-empty and without '/' (it prefixes its objects' names: \"" + group +
                  "/...\")");
  const JsonNode file = node.at("file");
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  if (!isGltfFile(*path))
    file.fail("an include is a glTF file (.gltf or .glb), got " + JsonNode::quoted(lowercaseExtension(*path)));
  GltfSceneChoice choice;
  if (const auto index = node.find("scene"))
    choice.scene = static_cast<std::size_t>(index->integer(0, std::numeric_limits<std::int32_t>::max()));
  if (const auto animation = node.find("animation")) choice.animation = animation->string();
  if (const auto rule = node.find("mirror_rule")) choice.mirrors = readMirrorRule(*rule);
  Result<ImportedGltfScene> imported = importGltfScene(*path, choice);
  if (!imported) file.fail(imported.error());
  Scene& included = imported->scene;
  for (const std::string& note : included.notes) scene.notes.push_back(file.string() + ": " + note);
  for (const Texture& texture : included.textures)
    if ((textures.texels += texture.texelCount()) > kMaxTexelsPerScene)
      file.fail("the scene's textures hold more than " + std::to_string(kMaxTexelsPerScene) +
                " texels with this file's; use smaller images");
  const auto meshOffset = static_cast<std::uint32_t>(scene.meshes.size());
  const auto materialOffset = static_cast<std::uint32_t>(scene.materials.size());
  const auto textureOffset = static_cast<std::uint32_t>(scene.textures.size());
  std::move(included.meshes.begin(), included.meshes.end(), std::back_inserter(scene.meshes));
  std::move(included.textures.begin(), included.textures.end(), std::back_inserter(scene.textures));
  for (Material& material : included.materials) {
    if (material.texture) *material.texture += textureOffset;
    material.name = group + "/" + material.name;
    scene.materials.push_back(std::move(material));
  }
  const math::Transform placement = readTransform(node, math::Transform{});
  mergeRig(std::move(included.rig), static_cast<std::uint32_t>(scene.objects.size()), group, scene.rig);
  for (SceneObject& object : included.objects) {
    object.name = names.objects.add(group + "/" + object.name, nameNode);
    object.mesh += meshOffset;
    object.material += materialOffset;
    if (object.mirror && object.mirror->closedTwinMesh) *object.mirror->closedTwinMesh += meshOffset;
    object.transform = placement;  // the group's meshes are in its world space, or its rig's
    scene.objects.push_back(std::move(object));
  }
}

}  // namespace specula::scene::file
