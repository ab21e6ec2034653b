#include "scene/file/FileAnimations.h"

#include <string_view>
#include <utility>

#include "scene/file/FileLimits.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

namespace {

// "keys" (each read by `readKey`, then given its "time") and "loop". Times must increase strictly.
template <class Path, class ReadKey>
Path readPath(const JsonNode& node, const ReadKey& readKey) {
  node.expectObject({"keys", "loop"});
  Path path;
  if (const auto loop = node.find("loop")) path.loop = loop->boolean();
  for (const JsonNode& keyNode : node.at("keys").array(1, kMaxKeys)) {
    auto key = readKey(keyNode);
    const JsonNode time = keyNode.at("time");
    key.time = time.number();
    if (!path.keys.empty() && !(key.time > path.keys.back().time))
      time.fail("key times must increase strictly; the previous key is at " +
                JsonNode::numberText(path.keys.back().time));
    path.keys.push_back(std::move(key));
  }
  return path;
}

}  // namespace

Animation readAnimation(const JsonNode& node, const Names& names, const Scene& scene) {
  node.expectObject({"target", "spin", "orbit", "path", "camera_path"});
  Animation animation;
  const JsonNode target = node.at("target");
  if (target.string() != "camera") animation.object = names.objects.find(target);
  const std::string_view kind = node.oneOf({"spin", "orbit", "path", "camera_path"});
  const JsonNode motion = node.at(kind);
  if (kind == "spin") {
    if (!animation.object)
      motion.fail("spin turns an object about its pivot; the camera can orbit or follow a camera_path");
    motion.expectObject({"axis", "degrees_per_second"});
    animation.motion = Spin{readDirection(motion.at("axis")), motion.at("degrees_per_second").number()};
  } else if (kind == "orbit") {
    motion.expectObject({"center", "axis", "degrees_per_second"});
    Orbit orbit;
    if (const auto center = motion.find("center")) orbit.center = center->vec3();
    orbit.axis = readDirection(motion.at("axis"));
    orbit.degreesPerSecond = motion.at("degrees_per_second").number();
    animation.motion = orbit;
  } else if (kind == "path") {
    if (!animation.object) motion.fail("path moves objects; move the camera with camera_path");
    const math::Transform& rest = scene.objects[*animation.object].transform;
    animation.motion = readPath<TransformPath>(motion, [&](const JsonNode& key) {
      key.expectObject({"time", "translation", "rotation", "scale"});
      return TransformKey{0.0, readTransform(key, rest)};
    });
  } else {
    if (animation.object) motion.fail("camera_path moves the camera; move objects with path");
    animation.motion = readPath<CameraPath>(motion, [&](const JsonNode& key) {
      key.expectObject({"time", "eye", "target", "up", "fov"});
      return CameraKey{0.0, readCamera(key, scene.camera)};
    });
  }
  return animation;
}

}  // namespace specula::scene::file
