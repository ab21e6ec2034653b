#include "scene/gltf/GltfSkins.h"

#include <cmath>
#include <string>

#include "scene/Deformation.h"
#include "scene/gltf/GltfAccessors.h"
#include "scene/gltf/GltfAnimations.h"

namespace specula::scene::gltf {

Result<RigSkin> readSkin(const tinygltf::Model& model, std::size_t skin,
                         const std::vector<std::optional<std::uint32_t>>& rigNode) {
  const tinygltf::Skin& source = model.skins[skin];
  const std::string where = "$.skins[" + std::to_string(skin) + "]";
  if (source.joints.empty()) return Error{where + ".joints: a skin needs at least one joint"};
  if (source.joints.size() > kMaxSkinJoints)
    return Error{where + ".joints: " + std::to_string(source.joints.size()) + " joints, more than the " +
                 std::to_string(kMaxSkinJoints) + " a skin may have"};
  RigSkin rig;
  for (std::size_t j = 0; j < source.joints.size(); ++j) {
    const int node = source.joints[j];
    const std::string at = where + ".joints[" + std::to_string(j) + "]";
    if (node < 0 || static_cast<std::size_t>(node) >= model.nodes.size())
      return Error{at + ": refers to node " + std::to_string(node) + ", but the file has " +
                   std::to_string(model.nodes.size())};
    if (!rigNode[static_cast<std::size_t>(node)])
      return Error{at + ": node " + std::to_string(node) + " is not in the scene drawn, so nothing can pose it"};
    rig.joints.push_back(*rigNode[static_cast<std::size_t>(node)]);
  }
  rig.inverseBind.assign(rig.joints.size(), glm::dmat4(1.0));
  if (source.inverseBindMatrices < 0) return rig;
  Result<Accessor> matrices = checkedAccessor(model, source.inverseBindMatrices, where + ".inverseBindMatrices",
                                              TINYGLTF_TYPE_MAT4, {TINYGLTF_COMPONENT_TYPE_FLOAT}, kMaxSkinJoints);
  if (!matrices) return Error{matrices.error()};
  if (matrices->count != rig.joints.size())
    return Error{matrices->name + ": " + std::to_string(matrices->count) + " matrices for " +
                 std::to_string(rig.joints.size()) + " joints; it needs one a joint"};
  for (std::size_t j = 0; j < rig.joints.size(); ++j) {
    for (std::size_t c = 0; c < 16; ++c) {
      const double value = matrices->component(j, c);
      if (!(std::abs(value) <= kMaxKeyMagnitude))
        return Error{matrices->name + ": matrix " + std::to_string(j) + " is not finite or has an entry beyond ±1e9"};
      rig.inverseBind[j][static_cast<glm::length_t>(c / 4)][static_cast<glm::length_t>(c % 4)] = value;
    }
    if (!(std::abs(glm::determinant(rig.inverseBind[j])) > 1e-18))
      return Error{matrices->name + ": matrix " + std::to_string(j) + " is singular"};
  }
  return rig;
}

}  // namespace specula::scene::gltf
