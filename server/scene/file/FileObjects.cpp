#include "scene/file/FileObjects.h"

#include "scene/file/FileMirrors.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

SceneObject readObject(const JsonNode& node, Names& names) {
  node.expectObject({"name", "mesh", "material", "translation", "rotation", "scale", "mirror", "reflected"});
  SceneObject object;
  const JsonNode name = node.at("name");
  object.name = names.objects.add(name);
  if (object.name == "camera") name.fail("\"camera\" is reserved: animations use it to target the camera");
  object.mesh = names.meshes.find(node.at("mesh"));
  object.material = names.materials.find(node.at("material"));
  object.transform = readTransform(node, math::Transform{});
  if (const auto mirror = node.find("mirror")) object.mirror = readMirror(*mirror, names.meshes);
  if (const auto reflected = node.find("reflected")) object.reflected = reflected->boolean();
  return object;
}

}  // namespace specula::scene::file
