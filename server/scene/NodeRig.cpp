#include "scene/NodeRig.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/Deformation.h"

namespace specula::scene {

namespace {

glm::dquat quaternion(const glm::dvec4& xyzw) { return glm::normalize(glm::dquat(xyzw.w, xyzw.x, xyzw.y, xyzw.z)); }
glm::dvec4 xyzw(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }

// t wrapped into [0, duration): clips loop, and a clock running backwards wraps the other way.
double clipTime(double seconds, double duration) {
  if (!(duration > 0.0)) return 0.0;
  const double t = std::fmod(seconds, duration);
  return t < 0.0 ? t + duration : t;
}

double clampedScale(double s) { return std::abs(s) >= kMinNodeScale ? s : std::copysign(kMinNodeScale, s); }

bool finite(const glm::dvec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

glm::dmat4 RigNode::local() const {
  if (matrix) return *matrix;
  return glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
}

glm::dvec4 NodeChannel::at(double seconds) const {
  const bool cubic = interpolation == KeyInterpolation::CubicSpline;
  const auto value = [&](std::size_t key) { return values[cubic ? 3 * key + 1 : key]; };
  if (times.size() == 1 || seconds <= times.front()) return value(0);
  if (seconds >= times.back()) return value(times.size() - 1);
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), seconds) - times.begin()) - 1;
  const double span = times[i + 1] - times[i], w = (seconds - times[i]) / span;
  switch (interpolation) {
    case KeyInterpolation::Step: return value(i);
    case KeyInterpolation::Linear:
      if (property == NodeProperty::Rotation)
        return xyzw(glm::slerp(quaternion(value(i)), quaternion(value(i + 1)), w));
      return glm::mix(value(i), value(i + 1), w);
    case KeyInterpolation::CubicSpline: {
      // Hermite spline of the glTF spec: the tangents are per second, so they scale by the key span.
      const double w2 = w * w, w3 = w2 * w;
      const glm::dvec4 outTangent = values[3 * i + 2], inTangent = values[3 * (i + 1)];
      const glm::dvec4 spline = (2 * w3 - 3 * w2 + 1) * value(i) + (w3 - 2 * w2 + w) * span * outTangent +
                                (-2 * w3 + 3 * w2) * value(i + 1) + (w3 - w2) * span * inTangent;
      return property == NodeProperty::Rotation ? xyzw(quaternion(spline)) : spline;
    }
  }
  return value(i);
}

std::vector<glm::dmat4> NodeRig::worldAt(double seconds) const {
  std::vector<RigNode> posed = nodes;
  for (const NodeClip& clip : clips) {
    const double t = clipTime(seconds, clip.duration);
    for (const NodeChannel& channel : clip.channels) {
      RigNode& node = posed[channel.node];
      switch (channel.property) {
        case NodeProperty::Translation: node.translation = glm::dvec3(channel.at(t)); break;
        case NodeProperty::Rotation: node.rotation = quaternion(channel.at(t)); break;
        case NodeProperty::Scale: node.scale = glm::dvec3(channel.at(t)); break;
        case NodeProperty::Weights: break;  // weightsAt's
      }
    }
  }
  std::vector<glm::dmat4> world(posed.size());
  for (std::size_t i = 0; i < posed.size(); ++i) {
    RigNode& node = posed[i];
    node.scale = {clampedScale(node.scale.x), clampedScale(node.scale.y), clampedScale(node.scale.z)};
    world[i] = node.parent ? world[*node.parent] * node.local() : node.local();
  }
  return world;
}

std::vector<std::vector<float>> NodeRig::weightsAt(double seconds) const {
  std::vector<std::vector<float>> weights;
  weights.reserve(morphed.size());
  for (const MorphedObject& object : morphed) weights.push_back(object.restWeights);
  for (const NodeClip& clip : clips) {
    const double t = clipTime(seconds, clip.duration);
    for (const NodeChannel& channel : clip.channels) {
      if (channel.property != NodeProperty::Weights) continue;
      const glm::dvec4 v = channel.at(t);
      for (std::size_t m = 0; m < morphed.size(); ++m) {
        if (morphed[m].node != channel.node) continue;
        for (std::size_t c = 0; c < 4 && channel.firstWeight + c < weights[m].size(); ++c)
          weights[m][channel.firstWeight + c] = static_cast<float>(v[static_cast<glm::length_t>(c)]);
      }
    }
  }
  return weights;
}

std::vector<std::vector<glm::mat4>> NodeRig::jointMatrices(const std::vector<glm::dmat4>& world) const {
  std::vector<std::vector<glm::mat4>> matrices;
  matrices.reserve(skinned.size());
  for (const SkinnedObject& object : skinned) matrices.push_back(skinMatrices(skins[object.skin], world, object.node));
  return matrices;
}

math::Camera NodeRig::cameraOf(const glm::dmat4& world, float fovYDegrees) {
  math::Camera camera;
  camera.eye = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  camera.target = camera.eye + glm::normalize(glm::vec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
  camera.up = glm::normalize(glm::vec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0)));
  camera.fovYDegrees = fovYDegrees;
  return camera;
}

std::optional<std::string> rigProblem(const NodeRig& rig, std::size_t objectCount) {
  for (std::size_t i = 0; i < rig.nodes.size(); ++i) {
    const RigNode& node = rig.nodes[i];
    const std::string where = "rig node " + std::to_string(i) + ": ";
    if (node.parent && *node.parent >= i) return where + "its parent must come before it";
    if (node.matrix) {
      for (int c = 0; c < 4; ++c)
        if (!finite((*node.matrix)[c])) return where + "matrix is not finite";
    } else if (!finite(glm::dvec4(node.translation, 0.0)) || !finite(glm::dvec4(node.scale, 0.0)) ||
               !finite(xyzw(node.rotation)) || std::abs(glm::length(node.rotation) - 1.0) > 1e-6) {
      return where + "needs a finite translation and scale and a unit rotation";
    }
  }
  for (const NodeClip& clip : rig.clips) {
    const std::string where = "clip '" + clip.name + "': ";
    double last = 0.0;
    for (const NodeChannel& channel : clip.channels) {
      if (channel.node >= rig.nodes.size()) return where + "a channel's node is out of range";
      if (rig.nodes[channel.node].matrix && channel.property != NodeProperty::Weights)
        return where + "a channel moves a matrix node";
      if (channel.times.empty() || !(channel.times.front() >= 0.0)) return where + "a channel needs times from 0 on";
      for (std::size_t k = 0; k < channel.times.size(); ++k)
        if (!std::isfinite(channel.times[k]) || (k > 0 && !(channel.times[k] > channel.times[k - 1])))
          return where + "a channel's times must be finite and increase strictly";
      const std::size_t perKey = channel.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
      if (channel.values.size() != perKey * channel.times.size()) return where + "a channel's values miscount its keys";
      if (!std::all_of(channel.values.begin(), channel.values.end(), finite)) return where + "a value is not finite";
      last = std::max(last, channel.times.back());
    }
    if (clip.channels.empty() || clip.duration != last) return where + "needs channels and their last time as duration";
  }
  for (const RiggedObject& rigged : rig.objects)
    if (rigged.object >= objectCount || rigged.node >= rig.nodes.size()) return "a rigged object is out of range";
  for (const RigSkin& skin : rig.skins) {
    if (skin.joints.empty() || skin.inverseBind.size() != skin.joints.size())
      return "a skin needs joints and one inverse bind matrix each";
    for (std::uint32_t joint : skin.joints)
      if (joint >= rig.nodes.size()) return "a skin's joint is out of range";
    for (const glm::dmat4& m : skin.inverseBind)
      for (int c = 0; c < 4; ++c)
        if (!finite(m[c])) return "an inverse bind matrix is not finite";
  }
  for (const SkinnedObject& object : rig.skinned)
    if (object.object >= objectCount || object.skin >= rig.skins.size() || object.node >= rig.nodes.size())
      return "a skinned object is out of range";
  for (const MorphedObject& object : rig.morphed) {
    if (object.object >= objectCount || object.node >= rig.nodes.size()) return "a morphed object is out of range";
    if (!std::all_of(object.restWeights.begin(), object.restWeights.end(), [](float w) { return std::isfinite(w); }))
      return "a morphed object's rest weights are not finite";
  }
  if (rig.camera && (rig.camera->node >= rig.nodes.size() || !(rig.camera->fovYDegrees > 0.0f) ||
                     !(rig.camera->fovYDegrees < 180.0f)))
    return "the rig's camera needs a node in range and a field of view in (0°, 180°)";
  return std::nullopt;
}

}  // namespace specula::scene
