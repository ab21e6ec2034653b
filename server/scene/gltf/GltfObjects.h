#pragma once
// The meshes on a glTF scene's nodes as scene objects: one per primitive, stored in world space.
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <glm/glm.hpp>
#include <set>
#include <string>
#include <vector>

#include "base/Result.h"
#include "scene/GltfImporter.h"
#include "scene/Mesh.h"
#include "scene/gltf/GltfMaterials.h"

namespace specula::scene::gltf {

// How a node's mesh changes shape: its morph targets' weights may animate, and its skin's joints move it
// when `skin` is set; whatever does not animate is applied once, at rest, when the mesh is placed.
struct NodeDeformation {
  bool weightsAnimate = false;
  std::optional<std::uint32_t> skin;  // the rig skin that poses the mesh every frame
  std::vector<glm::mat4> restJoints;  // the node's skin at rest (mesh space), empty without a skin
};

// Adds node meshes to the imported scene, each object under a name unique in the scene, with its
// material (a chrome one makes it a mirror of mixed curvature, two-sided where its mesh is open); at most
// kMaxVerticesPerScene vertices in all.
class ObjectPlacer {
 public:
  ObjectPlacer(const tinygltf::Model& model, MaterialTable& materials, ImportedGltfScene& imported);

  // Node `index`'s mesh, if it has one, placed at `world` (its rest pose); a singular transform leaves it
  // out, with a note. Under a `rigNode` the mesh stays in the node's space and the rig places its objects.
  // What of `deformation` animates needs a rigNode: the rig then deforms its objects, mirrors included.
  Status placeNodeMesh(std::size_t index, const glm::dmat4& world, std::optional<std::uint32_t> rigNode,
                       const NodeDeformation& deformation);

 private:
  std::string uniqueName(const std::string& wanted, const std::string& base);
  Status addObject(Mesh part, int material);

  const tinygltf::Model& model_;
  MaterialTable& materials_;
  ImportedGltfScene& imported_;
  std::size_t vertices_ = 0;
  std::set<std::string> names_;
};

}  // namespace specula::scene::gltf
