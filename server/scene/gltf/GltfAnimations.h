#pragma once
// A glTF file's animations as node clips: the ones chosen, their channels on translation, rotation, scale
// and morph target weights with LINEAR, STEP and CUBICSPLINE samplers, checked and named by JSONPath
// where broken.
#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/Result.h"
#include "scene/NodeRig.h"

namespace specula::scene::gltf {

// Keys a sampler may hold: far beyond any authored clip (a minute at 1 kHz), bounding memory per channel.
inline constexpr std::size_t kMaxKeysPerSampler = 1 << 16;
// Keyed values beyond this (metres, scale factors, tangents) are refused, so posed transforms stay finite in floats.
inline constexpr double kMaxKeyMagnitude = 1e9;

// The animations `choice` names ("all", "none", a name or an index), each a clip whose channels name
// nodes by `rigNode` (file node → rig node, nullopt for nodes outside the chosen scene, whose channels
// are dropped). A channel on weights becomes one channel for every four of the node's morph targets.
Result<std::vector<NodeClip>> readClips(const tinygltf::Model& model, const std::string& choice,
                                        const std::vector<std::optional<std::uint32_t>>& rigNode,
                                        std::vector<std::string>& notes);

}  // namespace specula::scene::gltf
