#include "scene/file/FileMirrors.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "scene/file/FileLimits.h"
#include "scene/file/FileValues.h"

namespace specula::scene::file {

namespace {

AnalyticShape readAnalyticShape(const JsonNode& node) {
  node.expectObject({"sphere", "ellipsoid", "exact_surface"});
  const std::string_view kind = node.oneOf({"sphere", "ellipsoid"});
  const JsonNode body = node.at(kind);
  AnalyticShape shape;
  if (kind == "sphere") {
    body.expectObject({"center", "radius"});
    shape.kind = AnalyticShape::Kind::Sphere;
    shape.radii = glm::vec3(static_cast<float>(body.at("radius").positive()));
  } else {
    body.expectObject({"center", "radii"});
    shape.kind = AnalyticShape::Kind::Ellipsoid;
    shape.radii = readPositiveVec3(body.at("radii"));
  }
  if (const auto center = body.find("center")) shape.center = center->vec3();
  if (const auto exact = node.find("exact_surface")) shape.exactSurface = exact->boolean();
  return shape;
}

// {"direction": [x, y, z], "axis_point": [x, y, z], "circle": radius} or "ellipse": [a, b] (semi-axes
// along u and v of math::Extrusion::along).
math::Extrusion readExtrusion(const JsonNode& node) {
  node.expectObject({"axis_point", "direction", "circle", "ellipse"});
  const std::string_view profile = node.oneOf({"circle", "ellipse"});
  glm::dvec2 radii;
  if (profile == "circle") {
    radii = glm::dvec2(node.at("circle").positive());
  } else {
    const JsonNode ellipse = node.at("ellipse");
    radii = glm::dvec2(ellipse.vec2());
    if (!(radii.x > 0.0 && radii.y > 0.0)) ellipse.fail("semi-axes must both be greater than 0");
  }
  const JsonNode direction = node.at("direction");
  const glm::dvec3 along(direction.vec3());
  if (!(glm::length(along) > 1e-6)) direction.fail("the extrusion direction must not be zero");
  const auto axisPoint = node.find("axis_point");
  return math::Extrusion::along(axisPoint ? glm::dvec3(axisPoint->vec3()) : glm::dvec3(0.0), along, radii);
}

// {"glTF material name": true | false, ...}: mirrors whatever their factors, or not.
std::map<std::string, bool> readMirrorMaterials(const JsonNode& node) {
  std::map<std::string, bool> materials;
  for (const auto& [name, mirror] : node.members(kMaxEntities)) materials[name] = mirror.boolean();
  return materials;
}

}  // namespace

MirrorInfo readMirror(const JsonNode& node, const NameIndex& meshes) {
  node.expectObject({"curvature", "closed", "closed_twin", "analytic", "extrusion"});
  MirrorInfo mirror;
  // Mixed (the default) lets the renderer split the mesh by its curvature (scene::MirrorParts).
  mirror.curvature = MirrorCurvature::Mixed;
  if (const std::optional<JsonNode> curvature = node.find("curvature")) {
    if (curvature->string() == "convex") mirror.curvature = MirrorCurvature::Convex;
    else if (curvature->string() == "concave") mirror.curvature = MirrorCurvature::Concave;
    else if (curvature->string() != "mixed")
      curvature->fail("unknown curvature " + JsonNode::quoted(curvature->string()) + "; use convex, concave or mixed");
  }
  const std::optional<JsonNode> twin = node.find("closed_twin");
  const std::optional<JsonNode> closed = node.find("closed");
  mirror.closed = closed ? closed->boolean() : !twin;  // open without a twin: two-sided, ray-cast
  if (mirror.closed && twin) twin->fail("only an open mirror takes a closed twin; drop it or set \"closed\": false");
  if (twin) mirror.closedTwinMesh = meshes.find(*twin);
  if (const auto analytic = node.find("analytic")) mirror.analytic = readAnalyticShape(*analytic);
  if (const auto extrusion = node.find("extrusion")) {
    if (mirror.analytic) extrusion->fail("a mirror is an analytic quadric or an extrusion, not both: keep one");
    // The 2-D reduction holds on the outside of a convex profile.
    const std::optional<JsonNode> curvature = node.find("curvature");
    if (curvature && mirror.curvature != MirrorCurvature::Convex)
      curvature->fail(
          "an extrusion mirror is convex (its profile is an ellipse); drop \"curvature\" or set it to \"convex\"");
    mirror.curvature = MirrorCurvature::Convex;
    mirror.extrusion = readExtrusion(*extrusion);
  }
  return mirror;
}

GltfMirrorRule readMirrorRule(const JsonNode& node) {
  node.expectObject({"metallic", "roughness", "materials"});
  GltfMirrorRule rule;
  if (const auto metallic = node.find("metallic")) rule.minMetallic = metallic->inRange(0.0, 1.0);
  if (const auto roughness = node.find("roughness")) rule.maxRoughness = roughness->inRange(0.0, 1.0);
  if (const auto materials = node.find("materials")) rule.materials = readMirrorMaterials(*materials);
  return rule;
}

}  // namespace specula::scene::file
