#include "passes/FrameContext.h"

#include <glm/gtc/matrix_transform.hpp>

namespace specula::passes {

glm::mat4 FrameView::worldToClip(glm::vec2 widen, float farScale) const {
  const glm::mat4 projection =
      glm::perspective(glm::radians(fovYDegrees), aspect, nearDistance, farDistance * farScale);
  return glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / widen.x, 1.0f / widen.y, 1.0f)) * projection * worldToView;
}

std::size_t FrameContext::searchMesh(std::size_t mirrorObject) const {
  const scene::SceneObject& object = scene.objects[mirrorObject];
  return object.mirror && object.mirror->closedTwinMesh ? *object.mirror->closedTwinMesh : object.mesh;
}

}  // namespace specula::passes
