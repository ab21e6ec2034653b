#include "scene/file/FileLights.h"

#include "scene/file/FileValues.h"

namespace specula::scene::file {

Light readLight(const JsonNode& node) {
  Light light;
  const JsonNode type = node.at("type");
  if (type.string() == "directional") {
    node.expectObject({"type", "direction", "color", "intensity"});
    light.kind = Light::Kind::Directional;
    light.vector = readDirection(node.at("direction"));
  } else if (type.string() == "point") {
    node.expectObject({"type", "position", "color", "intensity"});
    light.kind = Light::Kind::Point;
    light.vector = node.at("position").vec3();
  } else {
    type.fail("unknown light type " + JsonNode::quoted(type.string()) + "; use directional or point");
  }
  if (const auto color = node.find("color")) light.color = readColor(*color);
  if (const auto intensity = node.find("intensity")) light.intensity = static_cast<float>(intensity->atLeast(0.0));
  return light;
}

}  // namespace specula::scene::file
