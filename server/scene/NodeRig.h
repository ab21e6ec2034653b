#pragma once
// A node hierarchy moved by keyframed channels, as glTF animates: each node's translation, rotation and
// scale sampled at the scene time, composed down the tree, and the objects and camera carried by nodes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "math/Camera.h"

namespace specula::scene {

enum class KeyInterpolation { Step, Linear, CubicSpline };
enum class NodeProperty { Translation, Rotation, Scale, Weights };

// One property of one node over time. Rotations are quaternions (x, y, z, w in a vec4); translations and
// scales use xyz; morph target weights come four to a channel, from `firstWeight` on. A cubic spline
// stores three values per key: in-tangent, value, out-tangent.
struct NodeChannel {
  std::uint32_t node = 0;
  NodeProperty property = NodeProperty::Translation;
  std::uint32_t firstWeight = 0;  // Weights: the morph target of the value's x
  KeyInterpolation interpolation = KeyInterpolation::Linear;
  std::vector<double> times;       // seconds, ≥ 0, strictly increasing, at least one
  std::vector<glm::dvec4> values;  // times.size() values, or 3 × that for a cubic spline

  glm::dvec4 at(double seconds) const;  // before the first key the first value, after the last the last
};

// A named set of channels played together; it loops over [0, duration], as glTF viewers play clips.
struct NodeClip {
  std::string name;
  std::vector<NodeChannel> channels;
  double duration = 0.0;  // the last key time of any channel
};

// A node's rest transform: a fixed matrix, or translation · rotation · scale (what channels replace).
struct RigNode {
  std::optional<std::uint32_t> parent;  // always an earlier node: parents come first
  std::optional<glm::dmat4> matrix;     // set for matrix nodes, which glTF never animates
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};

  glm::dmat4 local() const;  // to the parent's space
};

// An object whose mesh is stored in its node's space: it is drawn at the node's world transform, after
// the object's own transform (an include's placement, a scene file's animations).
struct RiggedObject {
  std::uint32_t object = 0;
  std::uint32_t node = 0;
};

// An object whose mesh's morph target weights change with time: the node's weights channels set them,
// over its rest weights.
struct MorphedObject {
  std::uint32_t object = 0;
  std::uint32_t node = 0;
  std::vector<float> restWeights;  // one per morph target of the object's mesh
};

// A glTF skin: the nodes its joints are and each joint's inverse bind matrix (mesh space to the joint's
// space at bind time).
struct RigSkin {
  std::vector<std::uint32_t> joints;
  std::vector<glm::dmat4> inverseBind;  // one per joint
};

// An object whose mesh a skin deforms; its mesh is stored in the space of `node` (the mesh's node), so the
// joint matrices carry it from there: node world⁻¹ · joint world · inverse bind.
struct SkinnedObject {
  std::uint32_t object = 0;
  std::uint32_t skin = 0;
  std::uint32_t node = 0;
};

// The camera of a glTF camera node: eye at the node's origin, looking down its -z with its +y up.
struct RiggedCamera {
  std::uint32_t node = 0;
  float fovYDegrees = 45.0f;
};

// Scales of magnitude below this are drawn at it (sign kept), so a node scaled to zero by an animation
// (objects popping in) shrinks to a speck instead of making its transform singular.
inline constexpr double kMinNodeScale = 1e-4;

struct NodeRig {
  std::vector<RigNode> nodes;
  std::vector<NodeClip> clips;  // all played at once, each looping on its own duration
  std::vector<RiggedObject> objects;
  std::vector<MorphedObject> morphed;
  std::vector<RigSkin> skins;
  std::vector<SkinnedObject> skinned;
  std::optional<RiggedCamera> camera;

  bool moves() const { return !clips.empty(); }
  // Every node's transform to the rig's world at `seconds`.
  std::vector<glm::dmat4> worldAt(double seconds) const;
  // The weights of every entry of `morphed` at `seconds`, in its order.
  std::vector<std::vector<float>> weightsAt(double seconds) const;
  // The joint matrices of every entry of `skinned`, in its order, for the node transforms `world` (worldAt).
  std::vector<std::vector<glm::mat4>> jointMatrices(const std::vector<glm::dmat4>& world) const;
  static math::Camera cameraOf(const glm::dmat4& world, float fovYDegrees);
};

// A message naming the first broken node, channel or rigged object, or nullopt.
std::optional<std::string> rigProblem(const NodeRig& rig, std::size_t objectCount);

}  // namespace specula::scene
