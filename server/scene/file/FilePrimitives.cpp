#include "scene/file/FilePrimitives.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/Primitives.h"
#include "scene/file/FileLimits.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

Mesh readPrimitive(const JsonNode& node, std::string name) {
  const JsonNode type = node.at("type");
  const auto length = [&](std::string_view key) { return static_cast<float>(node.at(key).positive()); };
  const auto segments = [&](std::string_view key, std::int64_t low, int fallback) {
    const std::optional<JsonNode> count = node.find(key);
    return count ? static_cast<int>(count->integer(low, kMaxSegments)) : fallback;
  };
  if (type.string() == "grid") {
    node.expectObject({"type", "size", "cells"});
    const glm::vec2 size = node.at("size").vec2();
    if (!(size.x > 0.0f && size.y > 0.0f)) node.at("size").fail("components must both be greater than 0");
    glm::ivec2 cells{1, 1};
    if (const auto pair = node.find("cells")) {
      const std::vector<JsonNode> counts = pair->array(2, 2);
      cells = {static_cast<int>(counts[0].integer(1, kMaxSegments)),
               static_cast<int>(counts[1].integer(1, kMaxSegments))};
    }
    return primitives::grid(std::move(name), size.x, size.y, cells.x, cells.y);
  }
  if (type.string() == "sphere") {
    node.expectObject({"type", "radius", "slices", "stacks"});
    const float radius = length("radius");
    return primitives::uvSphere(std::move(name), radius, segments("slices", 3, 64), segments("stacks", 2, 32));
  }
  if (type.string() == "box") {
    node.expectObject({"type", "size"});
    return primitives::box(std::move(name), readPositiveVec3(node.at("size")));
  }
  if (type.string() == "cylinder") {
    node.expectObject({"type", "radius", "height", "slices", "capped"});
    const float radius = length("radius"), height = length("height");
    const std::optional<JsonNode> capped = node.find("capped");
    return primitives::cylinder(std::move(name), radius, height, segments("slices", 3, 48),
                                capped ? capped->boolean() : true);
  }
  if (type.string() == "torus") {
    node.expectObject({"type", "major_radius", "minor_radius", "major_segments", "minor_segments"});
    const float major = length("major_radius"), minor = length("minor_radius");
    return primitives::torus(std::move(name), major, minor, segments("major_segments", 3, 64),
                             segments("minor_segments", 3, 32));
  }
  if (type.string() == "lathe") {
    node.expectObject({"type", "profile", "slices"});
    std::vector<glm::vec2> profile;
    for (const JsonNode& point : node.at("profile").array(2, kMaxProfilePoints)) {
      profile.push_back(point.vec2());
      if (profile.back().x < 0.0f) point.fail("profile radius (the first number) must be at least 0");
    }
    return primitives::lathe(std::move(name), profile, segments("slices", 3, 64));
  }
  type.fail("unknown primitive type " + JsonNode::quoted(type.string()) +
            "; use grid, sphere, box, cylinder, torus or lathe");
}

}  // namespace specula::scene::file
