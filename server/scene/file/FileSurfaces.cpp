#include "scene/file/FileSurfaces.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "math/BSplineSurface.h"

namespace specula::scene::file {

std::vector<math::BezierPatch> readBezierPatches(const JsonNode& node) {
  std::vector<math::BezierPatch> patches;
  for (const JsonNode& patch : node.array(1, math::BSplineSurface::kMaxPatches)) {
    const std::vector<JsonNode> points = patch.array(16, 16);
    math::BezierPatch& bezier = patches.emplace_back();
    for (std::size_t i = 0; i < points.size(); ++i) bezier.points[i] = glm::dvec3(points[i].vec3());
  }
  return patches;
}

std::vector<math::BezierPatch> readBSpline(const JsonNode& node) {
  node.expectObject({"degree", "count", "knots_u", "knots_v", "points"});
  math::BSplineSurface surface;
  const auto pair = [&](std::string_view key, std::int64_t low, std::int64_t high) {
    const std::vector<JsonNode> values = node.at(key).array(2, 2);
    return glm::ivec2(static_cast<int>(values[0].integer(low, high)), static_cast<int>(values[1].integer(low, high)));
  };
  surface.degree = pair("degree", 1, math::BSplineSurface::kMaxDegree);
  surface.count = pair("count", 2, 4096);
  const auto knots = [&](std::string_view key, int count, int degree) {
    std::vector<double> values;
    for (const JsonNode& knot : node.at(key).array(0, 4096 + 4)) values.push_back(knot.number());
    if (values.size() != static_cast<std::size_t>(count + degree + 1))
      node.at(key).fail("has " + std::to_string(values.size()) + " knots; " + std::to_string(count) +
                        " points of degree " + std::to_string(degree) + " need " + std::to_string(count + degree + 1));
    return values;
  };
  surface.knotsU = knots("knots_u", surface.count.x, surface.degree.x);
  surface.knotsV = knots("knots_v", surface.count.y, surface.degree.y);
  const JsonNode points = node.at("points");
  const auto expected = static_cast<std::size_t>(surface.count.x) * static_cast<std::size_t>(surface.count.y);
  for (const JsonNode& point : points.array(expected, expected)) surface.controlNet.push_back(glm::dvec3(point.vec3()));
  if (auto problem = math::bsplineProblem(surface)) node.fail(*problem);
  return math::bezierPatchesOf(surface);
}

}  // namespace specula::scene::file
