#pragma once
// What the reference sees where a ray meets nothing: the scene's environment. The sky and the image's
// mapping are the definitions the GPU evaluates (shaders/common/environment-radiance.glsl); the image is
// read through TextureSampler at its finest level, as the GPU's textureLod(…, 0) reads it.
#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::reference {

glm::vec3 environmentRadiance(const scene::Scene& scene, const glm::vec3& direction);

}  // namespace specula::reference
