#include "passes/FrameContext.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math/Transform.h"

namespace specula::passes {

glm::mat4 FrameView::worldToClip(glm::vec2 widen, float farScale) const {
  const glm::mat4 projection =
      glm::perspective(glm::radians(fovYDegrees), aspect, nearDistance, farDistance * farScale);
  return glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / widen.x, 1.0f / widen.y, 1.0f)) *
         glm::translate(glm::mat4(1.0f), glm::vec3(jitterClip, 0.0f)) * projection * worldToView;
}

float FrameView::pixelAngle(int height) const {
  return 2.0f * std::tan(glm::radians(fovYDegrees) * 0.5f) / static_cast<float>(height);
}

glm::vec3 FrameView::forward() const {
  return -glm::normalize(glm::vec3(glm::inverse(worldToView)[2]));  // the view looks down its -z
}

std::size_t FrameContext::searchMesh(std::size_t mirrorObject) const {
  const scene::SceneObject& object = scene.objects[mirrorObject];
  return object.mirror && object.mirror->closedTwinMesh ? *object.mirror->closedTwinMesh : object.mesh;
}

glm::mat4 FrameContext::gbufferWorldToClip() const {
  return view.worldToClip(glm::vec2(reflections.coveredPixels()) / glm::vec2(target.width(), target.height()));
}

void FrameContext::setReflectedObject(const gl::ShaderProgram& program, const ReflectionSlotRange& range) const {
  const glm::mat4& objectToWorld = pose.objectToWorld[range.object];
  program.set("objectToWorld", objectToWorld);
  program.set("normalToWorld", math::normalMatrix(objectToWorld));
  program.set("firstSlot", static_cast<unsigned>(range.firstSlot));
}

}  // namespace specula::passes
