#include "scene/gltf/GltfLights.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace specula::scene::gltf {

// Intensities are relative to the brightest: glTF's lux and candela have no meaning for a one-bounce
// shading without falloff.
Status addLights(const tinygltf::Model& model, const std::vector<NodeAttachment>& lights, ImportedGltfScene& imported) {
  double brightest = 0.0;
  for (const NodeAttachment& attached : lights) {
    const int index = attached.index;
    if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size())
      return Error{"a node refers to light " + std::to_string(index) + ", but the file has " +
                   std::to_string(model.lights.size())};
    const double intensity = model.lights[static_cast<std::size_t>(index)].intensity;
    if (!std::isfinite(intensity) || intensity < 0.0)
      return Error{"light " + std::to_string(index) + ": intensity must be finite and >= 0"};
    brightest = std::max(brightest, intensity);
  }
  Scene& scene = imported.scene;
  for (const NodeAttachment& attached : lights) {
    const tinygltf::Light& source = model.lights[static_cast<std::size_t>(attached.index)];
    if (scene.lights.size() == kMaxLights) {
      imported.scene.notes.push_back("more than " + std::to_string(kMaxLights) + " lights: the rest are left out");
      break;
    }
    Light light;
    const glm::mat4 toWorld(attached.world);
    if (source.type == "directional") {
      light.kind = Light::Kind::Directional;
      light.vector = glm::normalize(glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)));  // it shines down -z
    } else {
      if (source.type == "spot")
        imported.scene.notes.push_back("light " + std::to_string(attached.index) +
                                       " is a spot light: drawn as a point light");
      light.kind = Light::Kind::Point;
      light.vector = glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    if (source.color.size() == 3 &&
        std::all_of(source.color.begin(), source.color.end(), [](double c) { return std::isfinite(c) && c >= 0.0; }))
      light.color = glm::vec3(source.color[0], source.color[1], source.color[2]);
    light.intensity = brightest > 0.0 ? static_cast<float>(source.intensity / brightest) : 0.0f;
    scene.lights.push_back(light);
  }
  if (scene.lights.empty()) {
    Light sun;
    sun.vector = glm::normalize(glm::vec3(0.4f, 1.0f, 0.6f));
    scene.lights.push_back(sun);
  }
  return {};
}

}  // namespace specula::scene::gltf
