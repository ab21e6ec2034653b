#pragma once
// What a ray that meets nothing sees: the frame's background and what every mirror reflects where its
// reflected ray leaves the scene. The sky and the image mapping are defined once for the GPU and the
// reference in shaders/common/environment-radiance.glsl.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "base/Result.h"
#include "common/environment-radiance.glsl"

namespace specula::scene {

struct Scene;

enum class EnvironmentKind {
  Colour = ENVIRONMENT_COLOUR,  // the scene's background colour in every direction ("none")
  Sky = ENVIRONMENT_SKY,        // the built-in procedural sky
  Image = ENVIRONMENT_IMAGE,    // an equirectangular image
};

struct Environment {
  EnvironmentKind kind = EnvironmentKind::Colour;
  std::optional<std::uint32_t> image;  // Image: the equirectangular texture, an index into Scene::textures
};

// The environment "sky" or "none" (the scene's background colour) names, or nullopt for any other word.
std::optional<Environment> namedEnvironment(std::string_view name);

// Makes the equirectangular PNG, JPEG or Radiance .hdr `file` the scene's environment (its u wraps round, its v stops
// at the poles), its texels counted against the scene's texture budget. Fails naming the file and the fix.
Status useEnvironmentImage(Scene& scene, const std::filesystem::path& file);

// `choice` as --environment takes it: "sky", "none" (the scene's background colour) or an image file.
Status chooseEnvironment(Scene& scene, const std::string& choice);

}  // namespace specula::scene
