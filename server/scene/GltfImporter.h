#pragma once
// glTF 2.0 import (tinygltf) from .gltf (JSON) or .glb (binary) files: one mesh's triangles for a
// JSON scene, or a whole glTF scene as a Specula scene.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include <variant>

#include "base/Result.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

namespace specula::scene {

// Which mesh of the file: by index, by name, or (monostate) the file's only mesh.
using GltfMeshSelector = std::variant<std::monostate, std::size_t, std::string>;

// The triangle primitives of the selected mesh, concatenated into one mesh named `meshName`, in the
// mesh's own space (node transforms are ignored; the scene places the object). Primitives without
// normals get flat normals, as the glTF spec asks; uv is TEXCOORD_0 or (0, 0). Images are never
// decoded. External buffers must be files inside the asset's folder; data: URIs are fine.
// Fails with a message naming the file and the problem for unreadable, malformed, hostile or oversized
// input: bad GLB framing, accessors outside their buffers, wrong component types, out-of-range indices,
// non-finite values, non-triangle primitives, more than kMaxVerticesPerScene vertices.
Result<Mesh> importGltf(const std::filesystem::path& file, const GltfMeshSelector& which, std::string meshName);

// A material becomes a mirror where it is this metallic and this smooth (pbrMetallicRoughness); its
// reflectivity is metallic × its base colour's brightest channel. On an open mesh it is a two-sided
// mirror that is ray-cast (MirrorInfo::twoSided).
inline constexpr double kGltfMirrorMetallic = 0.9, kGltfMirrorRoughness = 0.1;

// Which materials are mirrors: the thresholds above, or a scene file's own (its include's
// "mirror_rule"), and materials named one way or the other whatever their factors (a forced mirror
// reflects as if fully metallic).
struct GltfMirrorRule {
  double minMetallic = kGltfMirrorMetallic;
  double maxRoughness = kGltfMirrorRoughness;
  std::map<std::string, bool> materials;  // glTF material name → mirror or not; every name must be in the file
};

// Which glTF scene, camera and animations: unset, the file's default scene (else its first), the first
// camera met in its node tree (else a view framing the scene's bounds) and every animation; and which
// materials are mirrors.
struct GltfSceneChoice {
  std::optional<std::size_t> scene;
  std::optional<std::size_t> camera;
  GltfMirrorRule mirrors;
  std::string animation = "all";  // which animations play: all, none, a name or an index
};

struct ImportedGltfScene {
  Scene scene;  // its notes say what was read differently from the file, or left out
};

// The chosen glTF scene: every node with a mesh, at its world transform (TRS or matrix, composed
// down the tree; a node reached twice, by a cycle or a second parent, is refused), each primitive an
// object with its own material (base colour factor; metallic and smooth, a mirror of mixed curvature,
// two-sided on an open mesh), the chosen camera and the KHR_lights_punctual lights (a default light when
// there are none), and the chosen animations on the scene's rig. Meshes under a node an animation moves
// are stored in their node's space and drawn where the rig puts it; the rest in world space. Everything
// importGltf refuses is refused here too, with the file and the path to the problem (JSONPath for
// animations).
Result<ImportedGltfScene> importGltfScene(const std::filesystem::path& file, const GltfSceneChoice& choice);
// The same with the default choice.
Result<ImportedGltfScene> importGltfScene(const std::filesystem::path& file);

}  // namespace specula::scene
