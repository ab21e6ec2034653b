#include "scene/ScenePose.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace specula::scene {

namespace {

// Maps t onto [first key, last key]: wraps when looping, clamps otherwise.
template <class Keys>
double pathTime(const Keys& keys, bool loop, double t) {
  const double start = keys.front().time, end = keys.back().time;
  if (end <= start) return start;
  if (loop) return start + std::fmod(std::fmod(t - start, end - start) + (end - start), end - start);
  return std::clamp(t, start, end);
}

// Index i and blend weight w such that t lies between keys[i] and keys[i + 1].
template <class Keys>
std::pair<std::size_t, float> bracket(const Keys& keys, double t) {
  if (keys.size() == 1) return {0, 0.0f};
  auto next = std::upper_bound(keys.begin(), keys.end(), t, [](double v, const auto& k) { return v < k.time; });
  const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(next - keys.begin(), 1) - 1, keys.size() - 2);
  const double span = keys[i + 1].time - keys[i].time;
  return {i, static_cast<float>(std::clamp((t - keys[i].time) / span, 0.0, 1.0))};
}

math::Transform sample(const TransformPath& path, double t) {
  const auto [i, w] = bracket(path.keys, pathTime(path.keys, path.loop, t));
  if (path.keys.size() == 1) return path.keys[0].transform;
  const math::Transform& a = path.keys[i].transform;
  const math::Transform& b = path.keys[i + 1].transform;
  return {glm::mix(a.translation, b.translation, w), glm::slerp(a.rotation, b.rotation, w),
          glm::mix(a.scale, b.scale, w)};
}

math::Camera sample(const CameraPath& path, double t) {
  const auto [i, w] = bracket(path.keys, pathTime(path.keys, path.loop, t));
  if (path.keys.size() == 1) return path.keys[0].camera;
  const math::Camera& a = path.keys[i].camera;
  const math::Camera& b = path.keys[i + 1].camera;
  return {glm::mix(a.eye, b.eye, w), glm::mix(a.target, b.target, w), glm::mix(a.up, b.up, w),
          a.fovYDegrees + (b.fovYDegrees - a.fovYDegrees) * w};
}

// Angle in radians after t seconds, reduced first so large times keep float precision.
float angleAt(double degreesPerSecond, double t) {
  return static_cast<float>(glm::radians(std::fmod(degreesPerSecond * t, 360.0)));
}

}  // namespace

ScenePose ScenePose::at(const Scene& scene, double seconds) {
  std::vector<math::Transform> transforms;
  transforms.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects) transforms.push_back(object.transform);
  ScenePose pose;
  pose.seconds = seconds;
  pose.camera = scene.camera;

  for (const Animation& animation : scene.animations) {
    std::visit(
        [&](const auto& motion) {
          using Motion = std::decay_t<decltype(motion)>;
          if constexpr (std::is_same_v<Motion, CameraPath>) {
            pose.camera = sample(motion, seconds);
          } else if constexpr (std::is_same_v<Motion, TransformPath>) {
            transforms[*animation.object] = sample(motion, seconds);
          } else if constexpr (std::is_same_v<Motion, Spin>) {
            math::Transform& tr = transforms[*animation.object];
            tr.rotation = glm::angleAxis(angleAt(motion.degreesPerSecond, seconds), motion.axis) * tr.rotation;
          } else if constexpr (std::is_same_v<Motion, Orbit>) {
            const float angle = angleAt(motion.degreesPerSecond, seconds);
            if (animation.object) {
              math::Transform& tr = transforms[*animation.object];
              tr.translation = motion.center + glm::rotate(tr.translation - motion.center, angle, motion.axis);
              tr.rotation = glm::angleAxis(angle, motion.axis) * tr.rotation;
            } else {
              pose.camera.eye = motion.center + glm::rotate(pose.camera.eye - motion.center, angle, motion.axis);
            }
          }
        },
        animation.motion);
  }
  pose.objectToWorld.reserve(transforms.size());
  for (const math::Transform& tr : transforms) pose.objectToWorld.push_back(tr.matrix());
  pose.morphWeights.resize(scene.objects.size());
  pose.jointMatrices.resize(scene.objects.size());
  if (scene.rig.nodes.empty()) return pose;
  std::vector<std::vector<float>> weights = scene.rig.weightsAt(seconds);
  for (std::size_t m = 0; m < weights.size(); ++m)
    pose.morphWeights[scene.rig.morphed[m].object] = std::move(weights[m]);
  const std::vector<glm::dmat4> nodeToWorld = scene.rig.worldAt(seconds);
  std::vector<std::vector<glm::mat4>> joints = scene.rig.jointMatrices(nodeToWorld);
  for (std::size_t s = 0; s < joints.size(); ++s)
    pose.jointMatrices[scene.rig.skinned[s].object] = std::move(joints[s]);
  for (const RiggedObject& rigged : scene.rig.objects)
    pose.objectToWorld[rigged.object] =
        glm::mat4(glm::dmat4(pose.objectToWorld[rigged.object]) * nodeToWorld[rigged.node]);
  if (const auto& camera = scene.rig.camera)
    pose.camera = NodeRig::cameraOf(nodeToWorld[camera->node], camera->fovYDegrees);
  return pose;
}

}  // namespace specula::scene
