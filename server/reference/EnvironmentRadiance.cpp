#include "reference/EnvironmentRadiance.h"

#include "reference/TextureSampler.h"

namespace specula::reference {

glm::vec3 environmentRadiance(const scene::Scene& scene, const glm::vec3& direction) {
  switch (scene.environment.kind) {
    case scene::EnvironmentKind::Sky: return environment::proceduralSky(direction);
    case scene::EnvironmentKind::Image:
      return glm::vec3(
          sampleTexture(scene.textures.at(*scene.environment.image), environment::equirectangularUv(direction), 0.0f));
    case scene::EnvironmentKind::Colour: break;
  }
  return scene.background;
}

}  // namespace specula::reference
