#include "passes/ShadingUniforms.h"

#include <cassert>
#include <string>

namespace specula::passes {

void setSceneLighting(const gl::ShaderProgram& program, const scene::Scene& scene) {
  program.set("sceneAmbient", scene.ambient);
  const std::size_t count = scene.lights.size();
  assert(count <= scene::kMaxLights && "scenes must pass sceneProblem()");
  program.set("lightCount", static_cast<int>(count));
  for (std::size_t i = 0; i < count; ++i) {
    const scene::Light& light = scene.lights[i];
    const float w = light.kind == scene::Light::Kind::Point ? 1.0f : 0.0f;
    const std::string index = "[" + std::to_string(i) + "]";
    program.set(("lightVector" + index).c_str(), glm::vec4(light.vector, w));
    program.set(("lightColor" + index).c_str(), light.color * light.intensity);
  }
}

void setMaterial(const gl::ShaderProgram& program, const scene::Material& material, const GpuTextures& textures) {
  textures.bind(material.texture);
  program.set("materialTexture", static_cast<int>(GpuTextures::kMaterialTextureUnit));
  program.set("materialHasTexture", material.texture ? 1 : 0);
  program.set("materialBaseColor", material.baseColor);
  program.set("materialUnlit", material.unlit ? 1 : 0);
  program.set("materialHasChecker", material.checker ? 1 : 0);
  if (material.checker) {
    program.set("materialCheckerOddColor", material.checker->oddColor);
    program.set("materialCheckerCellsPerUnit", material.checker->cellsPerUnit);
  }
}

void setEnvironment(const gl::ShaderProgram& program, const scene::Scene& scene, const GpuTextures& textures) {
  program.set("environmentKind", static_cast<int>(scene.environment.kind));
  program.set("environmentColour", scene.background);
  textures.bindEnvironment(scene.environment.image);
}

void setRayCone(const gl::ShaderProgram& program, const FrameContext& frame) {
  program.set("viewForward", frame.view.forward());
  program.set("pixelAngle", frame.view.pixelAngle(frame.target.height()));
}

}  // namespace specula::passes
