#include "scene/gltf/GltfAnimations.h"

#include <algorithm>
#include <cmath>

#include "scene/gltf/GltfAccessors.h"

namespace specula::scene::gltf {

namespace {

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

// The indices of the animations `choice` names: "all", "none", a name, or an index.
Result<std::vector<std::size_t>> chosenAnimations(const tinygltf::Model& model, const std::string& choice) {
  std::vector<std::size_t> chosen;
  if (choice == "none") return chosen;
  if (choice == "all") {
    for (std::size_t a = 0; a < model.animations.size(); ++a) chosen.push_back(a);
    return chosen;
  }
  for (std::size_t a = 0; a < model.animations.size(); ++a)
    if (model.animations[a].name == choice) return std::vector<std::size_t>{a};
  const bool digits = !choice.empty() && choice.size() < 10 &&
                      std::all_of(choice.begin(), choice.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (digits && std::stoul(choice) < model.animations.size()) return std::vector<std::size_t>{std::stoul(choice)};
  std::string names;
  for (std::size_t a = 0; a < model.animations.size(); ++a)
    names += (names.empty() ? "" : ", ") + std::to_string(a) +
             (model.animations[a].name.empty() ? "" : " " + quoted(model.animations[a].name));
  return Error{"there is no animation " + quoted(choice) + " (the file has " +
               (names.empty() ? std::string("none") : names) +
               "); name one, or all or none, with --animation or \"animation\" in an include"};
}

Result<KeyInterpolation> interpolationOf(const tinygltf::AnimationSampler& sampler, const std::string& where) {
  if (sampler.interpolation == "LINEAR") return KeyInterpolation::Linear;
  if (sampler.interpolation == "STEP") return KeyInterpolation::Step;
  if (sampler.interpolation == "CUBICSPLINE") return KeyInterpolation::CubicSpline;
  return Error{where + ".interpolation: " + quoted(sampler.interpolation) + " is not LINEAR, STEP or CUBICSPLINE"};
}

// Key times: finite, from 0 on, strictly increasing, as the glTF spec requires of a sampler's input.
Result<std::vector<double>> readTimes(const tinygltf::Model& model, int input, const std::string& where) {
  Result<Accessor> accessor =
      checkedAccessor(model, input, where, TINYGLTF_TYPE_SCALAR, {TINYGLTF_COMPONENT_TYPE_FLOAT}, kMaxKeysPerSampler);
  if (!accessor) return Error{accessor.error()};
  std::vector<double> times(accessor->count);
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = accessor->component(k, 0);
    if (!std::isfinite(times[k]) || times[k] < 0.0 || (k > 0 && !(times[k] > times[k - 1])))
      return Error{accessor->name + ": key " + std::to_string(k) + " is at " + std::to_string(times[k]) +
                   " s; key times must be finite, from 0 on and strictly increasing"};
  }
  return times;
}

Result<std::vector<glm::dvec4>> readValues(const tinygltf::Model& model, int output, const NodeChannel& channel,
                                           const std::string& where) {
  const bool rotation = channel.property == NodeProperty::Rotation;
  const std::size_t perKey = channel.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
  const std::initializer_list<int> floatOnly = {TINYGLTF_COMPONENT_TYPE_FLOAT};
  const std::initializer_list<int> quaternions = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  Result<Accessor> accessor = checkedAccessor(model, output, where, rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3,
                                              rotation ? quaternions : floatOnly, 3 * kMaxKeysPerSampler);
  if (!accessor) return Error{accessor.error()};
  if (accessor->count != perKey * channel.times.size())
    return Error{
        accessor->name + ": " + std::to_string(accessor->count) + " values for " +
        std::to_string(channel.times.size()) + " keys" +
        (perKey == 3 ? "; CUBICSPLINE needs 3 a key (in-tangent, value, out-tangent)" : "; it needs one a key")};
  std::vector<glm::dvec4> values(accessor->count);
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (int c = 0; c < (rotation ? 4 : 3); ++c) values[i][c] = accessor->component(i, static_cast<std::size_t>(c));
    const double largest =
        std::max({std::abs(values[i].x), std::abs(values[i].y), std::abs(values[i].z), std::abs(values[i].w)});
    if (!(largest <= kMaxKeyMagnitude))  // also false for NaN
      return Error{accessor->name + ": value " + std::to_string(i) + " is not finite or has a component beyond ±" +
                   std::to_string(static_cast<long long>(kMaxKeyMagnitude))};
    const bool keyValue = perKey == 1 || i % 3 == 1;  // a cubic spline's tangents may be zero
    if (rotation && keyValue && glm::length(values[i]) < 1e-6)
      return Error{accessor->name + ": value " + std::to_string(i) + " is a zero quaternion, which is no rotation"};
  }
  return values;
}

Result<NodeProperty> propertyOf(const std::string& path, const std::string& where) {
  if (path == "translation") return NodeProperty::Translation;
  if (path == "rotation") return NodeProperty::Rotation;
  if (path == "scale") return NodeProperty::Scale;
  return Error{where + ".target.path: " + quoted(path) + " is not translation, rotation, scale or weights"};
}

}  // namespace

Result<std::vector<NodeClip>> readClips(const tinygltf::Model& model, const std::string& choice,
                                        const std::vector<std::optional<std::uint32_t>>& rigNode,
                                        std::vector<std::string>& notes) {
  Result<std::vector<std::size_t>> chosen = chosenAnimations(model, choice);
  if (!chosen) return Error{chosen.error()};
  if (const std::size_t left = model.animations.size() - chosen->size(); left > 0)
    notes.push_back(std::to_string(left) + (left == 1 ? " animation" : " animations") + " not played (--animation " +
                    choice + "; all plays every one)");
  std::vector<NodeClip> clips;
  std::size_t weightChannels = 0;
  for (std::size_t a : chosen.value()) {
    const tinygltf::Animation& animation = model.animations[a];
    NodeClip clip;
    clip.name = animation.name.empty() ? "animation " + std::to_string(a) : animation.name;
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& source = animation.channels[c];
      const std::string where = "$.animations[" + std::to_string(a) + "].channels[" + std::to_string(c) + "]";
      if (source.sampler < 0 || static_cast<std::size_t>(source.sampler) >= animation.samplers.size())
        return Error{where + ".sampler: refers to sampler " + std::to_string(source.sampler) +
                     ", but the animation has " + std::to_string(animation.samplers.size())};
      if (source.target_node < 0 || static_cast<std::size_t>(source.target_node) >= model.nodes.size())
        return Error{where + ".target.node: refers to node " + std::to_string(source.target_node) +
                     ", but the file has " + std::to_string(model.nodes.size())};
      if (source.target_path == "weights") {
        ++weightChannels;
        continue;
      }
      Result<NodeProperty> property = propertyOf(source.target_path, where);
      if (!property) return Error{property.error()};
      const auto node = static_cast<std::size_t>(source.target_node);
      if (!model.nodes[node].matrix.empty())
        return Error{where + ".target.node: node " + std::to_string(node) +
                     " has a matrix; glTF animates only nodes given by translation, rotation and scale"};
      const std::string samplerAt =
          "$.animations[" + std::to_string(a) + "].samplers[" + std::to_string(source.sampler) + "]";
      const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(source.sampler)];
      NodeChannel channel;
      channel.property = property.value();
      Result<KeyInterpolation> interpolation = interpolationOf(sampler, samplerAt);
      if (!interpolation) return Error{interpolation.error()};
      channel.interpolation = interpolation.value();
      Result<std::vector<double>> times = readTimes(model, sampler.input, samplerAt + ".input");
      if (!times) return Error{times.error()};
      channel.times = std::move(times).value();
      Result<std::vector<glm::dvec4>> values = readValues(model, sampler.output, channel, samplerAt + ".output");
      if (!values) return Error{values.error()};
      channel.values = std::move(values).value();
      if (!rigNode[node]) continue;  // a node of another scene: nothing here moves
      channel.node = *rigNode[node];
      clip.duration = std::max(clip.duration, channel.times.back());
      clip.channels.push_back(std::move(channel));
    }
    if (!clip.channels.empty()) clips.push_back(std::move(clip));
  }
  if (weightChannels > 0)
    notes.push_back(std::to_string(weightChannels) +
                    (weightChannels == 1 ? " animation channel drives" : " animation channels drive") +
                    " morph target weights, not played (morph targets are not read yet)");
  return clips;
}

}  // namespace specula::scene::gltf
