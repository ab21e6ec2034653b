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

// Morph targets the mesh of `node` has (every primitive of a mesh has as many), 0 without a mesh.
std::size_t morphTargetCount(const tinygltf::Model& model, std::size_t node) {
  const int mesh = model.nodes[node].mesh;
  if (mesh < 0 || static_cast<std::size_t>(mesh) >= model.meshes.size()) return 0;
  const auto& primitives = model.meshes[static_cast<std::size_t>(mesh)].primitives;
  return primitives.empty() ? 0 : primitives.front().targets.size();
}

// A channel's values, `width` numbers a value: a vector of 3 or 4, or a key's `width` morph target weights.
// `accessorName` gets the accessor's name for messages.
Result<std::vector<double>> readNumbers(const tinygltf::Model& model, int output, const NodeChannel& channel,
                                        std::size_t width, const std::string& where, std::string& accessorName) {
  const std::size_t perKey = channel.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
  const std::initializer_list<int> floatOnly = {TINYGLTF_COMPONENT_TYPE_FLOAT};
  const std::initializer_list<int> normalized = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  const bool rotation = channel.property == NodeProperty::Rotation;
  const bool weights = channel.property == NodeProperty::Weights;
  const int type = weights ? TINYGLTF_TYPE_SCALAR : rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
  const std::size_t elementsPerValue = weights ? width : 1;
  Result<Accessor> accessor = checkedAccessor(model, output, where, type, rotation || weights ? normalized : floatOnly,
                                              3 * kMaxKeysPerSampler * elementsPerValue);
  if (!accessor) return Error{accessor.error()};
  accessorName = accessor->name;
  if (accessor->count != perKey * channel.times.size() * elementsPerValue)
    return Error{
        accessor->name + ": " + std::to_string(accessor->count) + " values for " +
        std::to_string(channel.times.size()) + " keys" +
        (weights ? " of " + std::to_string(width) + " morph target weights" : "") +
        (perKey == 3 ? "; CUBICSPLINE needs 3 a key (in-tangent, value, out-tangent)" : "; it needs one a key")};
  std::vector<double> numbers(perKey * channel.times.size() * width);
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    numbers[i] = weights ? accessor->component(i, 0) : accessor->component(i / width, i % width);
    if (!(std::abs(numbers[i]) <= kMaxKeyMagnitude))  // also false for NaN
      return Error{accessor->name + ": value " + std::to_string(weights ? i : i / width) +
                   " is not finite or has a component beyond ±" +
                   std::to_string(static_cast<long long>(kMaxKeyMagnitude))};
  }
  return numbers;
}

Result<std::vector<glm::dvec4>> readValues(const tinygltf::Model& model, int output, const NodeChannel& channel,
                                           const std::string& where) {
  const bool rotation = channel.property == NodeProperty::Rotation;
  const std::size_t width = rotation ? 4 : 3;
  std::string name;
  Result<std::vector<double>> numbers = readNumbers(model, output, channel, width, where, name);
  if (!numbers) return Error{numbers.error()};
  const std::size_t perKey = channel.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
  std::vector<glm::dvec4> values(numbers->size() / width);
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t c = 0; c < width; ++c) values[i][static_cast<glm::length_t>(c)] = (*numbers)[i * width + c];
    const bool keyValue = perKey == 1 || i % 3 == 1;  // a cubic spline's tangents may be zero
    if (rotation && keyValue && glm::length(values[i]) < 1e-6)
      return Error{name + ": value " + std::to_string(i) + " is a zero quaternion, which is no rotation"};
  }
  return values;
}

// A weights channel of `width` targets as channels of four weights each (the last one padded with zeros).
std::vector<NodeChannel> weightChannels(const NodeChannel& shape, const std::vector<double>& numbers,
                                        std::size_t width) {
  std::vector<NodeChannel> channels;
  for (std::size_t first = 0; first < width; first += 4) {
    NodeChannel channel = shape;
    channel.firstWeight = static_cast<std::uint32_t>(first);
    channel.values.resize(numbers.size() / width);
    for (std::size_t v = 0; v < channel.values.size(); ++v)
      for (std::size_t c = 0; c < 4 && first + c < width; ++c)
        channel.values[v][static_cast<glm::length_t>(c)] = numbers[v * width + first + c];
    channels.push_back(std::move(channel));
  }
  return channels;
}

Result<NodeProperty> propertyOf(const std::string& path, const std::string& where) {
  if (path == "translation") return NodeProperty::Translation;
  if (path == "rotation") return NodeProperty::Rotation;
  if (path == "scale") return NodeProperty::Scale;
  if (path == "weights") return NodeProperty::Weights;
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
      Result<NodeProperty> property = propertyOf(source.target_path, where);
      if (!property) return Error{property.error()};
      const auto node = static_cast<std::size_t>(source.target_node);
      const bool weights = property.value() == NodeProperty::Weights;
      const std::size_t targets = morphTargetCount(model, node);
      if (weights && targets == 0)
        return Error{where + ".target.node: node " + std::to_string(node) +
                     " has no mesh with morph targets for its weights to drive"};
      if (!weights && !model.nodes[node].matrix.empty())
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
      std::vector<NodeChannel> read;
      if (weights) {
        std::string name;
        Result<std::vector<double>> numbers =
            readNumbers(model, sampler.output, channel, targets, samplerAt + ".output", name);
        if (!numbers) return Error{numbers.error()};
        read = weightChannels(channel, numbers.value(), targets);
      } else {
        Result<std::vector<glm::dvec4>> values = readValues(model, sampler.output, channel, samplerAt + ".output");
        if (!values) return Error{values.error()};
        channel.values = std::move(values).value();
        read.push_back(std::move(channel));
      }
      if (!rigNode[node]) continue;  // a node of another scene: nothing here moves
      for (NodeChannel& each : read) {
        each.node = *rigNode[node];
        clip.duration = std::max(clip.duration, each.times.back());
        clip.channels.push_back(std::move(each));
      }
    }
    if (!clip.channels.empty()) clips.push_back(std::move(clip));
  }
  return clips;
}

}  // namespace specula::scene::gltf
