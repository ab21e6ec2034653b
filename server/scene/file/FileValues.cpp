#include "scene/file/FileValues.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "math/Color.h"

namespace specula::scene::file {

glm::vec3 readColor(const JsonNode& node) {
  glm::vec3 srgb;
  if (node.isString()) {
    const std::string& text = node.string();
    const bool hex = text.size() == 7 && text[0] == '#' && std::all_of(text.begin() + 1, text.end(), [](char c) {
                       return std::isxdigit(static_cast<unsigned char>(c));
                     });
    if (!hex)
      node.fail(JsonNode::quoted(text) + " is not a colour; use \"#rrggbb\" or [r, g, b] with components in [0, 1]");
    for (glm::length_t i = 0; i < 3; ++i)
      srgb[i] =
          static_cast<float>(std::stoi(text.substr(1 + 2 * static_cast<std::size_t>(i), 2), nullptr, 16)) / 255.0f;
  } else {
    if (!node.isArray()) node.fail("expected a colour (\"#rrggbb\" or [r, g, b]), got " + node.typeName());
    const std::vector<JsonNode> components = node.array(3, 3);
    for (glm::length_t i = 0; i < 3; ++i)
      srgb[i] = static_cast<float>(components[static_cast<std::size_t>(i)].inRange(0.0, 1.0));
  }
  return math::srgbToLinear(srgb);
}

glm::vec3 readDirection(const JsonNode& node) {
  const glm::dvec3 v{node.vec3()};
  const double length = glm::length(v);
  if (!(length > 1e-9)) node.fail("must be a non-zero vector");
  return glm::vec3(v / length);
}

glm::vec3 readPositiveVec3(const JsonNode& node) {
  const glm::vec3 v = node.vec3();
  if (!glm::all(glm::greaterThan(v, glm::vec3(0.0f)))) node.fail("components must all be greater than 0");
  return v;
}

glm::quat readRotation(const JsonNode& node) {
  node.expectObject({"axis", "degrees", "quaternion"});
  if (node.oneOf({"axis", "quaternion"}) == "quaternion") {
    if (const auto degrees = node.find("degrees"))
      degrees->fail("\"degrees\" goes with \"axis\", not with \"quaternion\"");
    const JsonNode quaternion = node.at("quaternion");
    const glm::dvec4 q{quaternion.vec4()};
    const double length = glm::length(q);
    if (!(length > 1e-9)) quaternion.fail("must not be zero");
    return glm::quat(static_cast<float>(q.w / length), static_cast<float>(q.x / length),
                     static_cast<float>(q.y / length), static_cast<float>(q.z / length));
  }
  const float degrees = static_cast<float>(node.at("degrees").number());
  return glm::angleAxis(glm::radians(degrees), readDirection(node.at("axis")));
}

glm::vec3 readScale(const JsonNode& node) {
  if (node.isNumber()) return glm::vec3(static_cast<float>(node.positive()));
  return readPositiveVec3(node);
}

math::Transform readTransform(const JsonNode& node, math::Transform transform) {
  if (const auto n = node.find("translation")) transform.translation = n->vec3();
  if (const auto n = node.find("rotation")) transform.rotation = readRotation(*n);
  if (const auto n = node.find("scale")) transform.scale = readScale(*n);
  return transform;
}

math::Camera readCamera(const JsonNode& node, math::Camera camera) {
  camera.eye = node.at("eye").vec3();
  camera.target = node.at("target").vec3();
  if (const auto up = node.find("up")) camera.up = up->vec3();
  if (const auto fov = node.find("fov")) {
    const double degrees = fov->number();
    if (!(degrees > 0.0 && degrees < 180.0))
      fov->fail("field of view must lie in (0, 180) degrees, got " + JsonNode::numberText(degrees));
    camera.fovYDegrees = static_cast<float>(degrees);
  }
  if (auto problem = math::cameraProblem(camera)) node.fail(*problem);
  return camera;
}

}  // namespace specula::scene::file
