#include "scene/gltf/GltfCamera.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "math/Bounds.h"
#include "scene/ScenePose.h"

namespace specula::scene::gltf {

namespace {

// A view of the scene's bounds at time 0 from the front, above and to the right, the whole box in a 45° frame.
math::Camera framingCamera(const Scene& scene) {
  math::Bounds bounds;
  const ScenePose pose = ScenePose::at(scene, 0.0);
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    for (const Vertex& v : scene.meshes[scene.objects[i].mesh].vertices)
      bounds.add(glm::vec3(pose.objectToWorld[i] * glm::vec4(v.position, 1.0f)));
  const glm::vec3 centre = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  math::Camera camera;
  camera.fovYDegrees = 45.0f;
  camera.target = centre;
  camera.eye =
      centre + radius / std::sin(glm::radians(0.5f * camera.fovYDegrees)) * glm::normalize(glm::vec3(0.5f, 0.4f, 1.0f));
  return camera;
}

}  // namespace

Status placeCamera(const tinygltf::Model& model, const std::vector<NodeAttachment>& cameras,
                   std::optional<std::size_t> wanted, std::size_t sceneIndex, ImportedGltfScene& imported) {
  if (wanted && *wanted >= model.cameras.size())
    return Error{"there is no camera " + std::to_string(*wanted) + " (the file has " +
                 std::to_string(model.cameras.size()) + ")"};
  const auto placed = std::find_if(cameras.begin(), cameras.end(), [&](const NodeAttachment& c) {
    return !wanted || static_cast<std::size_t>(c.index) == *wanted;
  });
  Scene& scene = imported.scene;
  scene.camera = framingCamera(scene);
  if (placed == cameras.end()) {
    if (wanted)
      return Error{"camera " + std::to_string(*wanted) + " is on no node of scene " + std::to_string(sceneIndex)};
  } else if (placed->index < 0 || static_cast<std::size_t>(placed->index) >= model.cameras.size()) {
    return Error{"a node refers to camera " + std::to_string(placed->index) + ", but the file has " +
                 std::to_string(model.cameras.size())};
  } else if (model.cameras[static_cast<std::size_t>(placed->index)].type != "perspective") {
    imported.scene.notes.push_back("camera " + std::to_string(placed->index) +
                                   " is not perspective: the view frames the scene instead");
  } else {
    const double yfov = model.cameras[static_cast<std::size_t>(placed->index)].perspective.yfov;
    const auto fovYDegrees = static_cast<float>(glm::degrees(yfov));
    const math::Camera camera = NodeRig::cameraOf(placed->world, fovYDegrees);
    if (auto problem = math::cameraProblem(camera))
      return Error{"camera " + std::to_string(placed->index) + ": " + *problem};
    scene.camera = camera;
    if (placed->rigNode) scene.rig.camera = RiggedCamera{*placed->rigNode, fovYDegrees};
  }
  return {};
}

}  // namespace specula::scene::gltf
