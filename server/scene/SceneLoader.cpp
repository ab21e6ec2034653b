#include "scene/SceneLoader.h"

#include <algorithm>
#include <cctype>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <iterator>
#include <map>
#include <optional>

#include "math/BSplineSurface.h"

#include "math/Color.h"
#include "scene/AssetFiles.h"
#include "scene/GltfImporter.h"
#include "scene/JsonNode.h"
#include "scene/MeshSubdivision.h"
#include "scene/NameIndex.h"
#include "scene/ObjImporter.h"
#include "scene/ParametricMesh.h"
#include "scene/Primitives.h"
#include "scene/SceneChecks.h"
#include "scene/StrictJson.h"

namespace specula::scene {

namespace {

namespace fs = std::filesystem;

// Bounds on lists and tessellation, so no file allocates without limit before the vertex budget applies.
constexpr std::size_t kMaxEntities = 10000;  // meshes, materials, objects, animations, each
constexpr std::size_t kMaxKeys = 100000;     // keyframes per path
constexpr std::size_t kMaxProfilePoints = 1024;
constexpr std::int64_t kMaxSegments = 1024;  // grid cells per side, slices, stacks, torus segments
constexpr std::size_t kMaxIncludes = 64;     // glTF files included, each read whole

// Names of everything a scene file refers to by name.
struct Names {
  NameIndex meshes{"mesh"};
  NameIndex materials{"material"};
  NameIndex objects{"object"};
};

// sRGB "#rrggbb" or [r, g, b] in [0, 1], returned as linear RGB.
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

// Any non-zero vector, normalized.
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

// {"axis": [x, y, z], "degrees": a} or {"quaternion": [x, y, z, w]}; the quaternion is normalized.
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

// A positive number (uniform) or [x, y, z] of positive numbers; mirrored (negative) scales would flip winding.
glm::vec3 readScale(const JsonNode& node) {
  if (node.isNumber()) return glm::vec3(static_cast<float>(node.positive()));
  return readPositiveVec3(node);
}

// Applies the "translation", "rotation" and "scale" keys present in `node` to `transform`.
math::Transform readTransform(const JsonNode& node, math::Transform transform) {
  if (const auto n = node.find("translation")) transform.translation = n->vec3();
  if (const auto n = node.find("rotation")) transform.rotation = readRotation(*n);
  if (const auto n = node.find("scale")) transform.scale = readScale(*n);
  return transform;
}

// "eye" and "target" (required), "up" and "fov" (defaulting to `camera`'s); the caller checks the keys.
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

// [[16 × [x, y, z]], ...]: bicubic Bézier patches, each four rows of four control points (u along a row).
std::vector<math::BezierPatch> readBezierPatches(const JsonNode& node) {
  std::vector<math::BezierPatch> patches;
  for (const JsonNode& patch : node.array(1, math::BSplineSurface::kMaxPatches)) {
    const std::vector<JsonNode> points = patch.array(16, 16);
    math::BezierPatch& bezier = patches.emplace_back();
    for (std::size_t i = 0; i < points.size(); ++i) bezier.points[i] = glm::dvec3(points[i].vec3());
  }
  return patches;
}

// {"degree": [du, dv], "count": [nu, nv], "knots_u": [...], "knots_v": [...], "points": [nu·nv × [x, y, z]]}:
// a tensor-product B-spline surface, rows of nu points along u, nv rows along v.
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

GltfMeshSelector readMeshSelector(const JsonNode& node) {
  if (node.isString()) return node.string();
  if (node.isNumber()) return static_cast<std::size_t>(node.integer(0, std::numeric_limits<std::int32_t>::max()));
  node.fail("expected a mesh index or name, got " + node.typeName());
}

Mesh readMeshSource(const JsonNode& node, const fs::path& baseDir, std::string name) {
  const std::optional<JsonNode> pick = node.find("mesh");
  const std::string_view source = node.oneOf({"file", "primitive", "bezier_patches", "bspline"});
  const std::optional<JsonNode> segments = node.find("segments");
  if (segments && source != "bezier_patches" && source != "bspline")
    segments->fail("\"segments\" sets the grid of a parametric surface (bezier_patches or bspline) only");
  if (source == "bezier_patches" || source == "bspline") {
    if (pick) pick->fail("\"mesh\" picks a mesh inside a glTF \"file\"; a parametric surface has none");
    std::vector<math::BezierPatch> patches =
        source == "bspline" ? readBSpline(node.at("bspline")) : readBezierPatches(node.at("bezier_patches"));
    const int perSide = segments ? static_cast<int>(segments->integer(1, 64)) : kDefaultPatchSegments;
    const std::size_t vertices = patches.size() * static_cast<std::size_t>((perSide + 1) * (perSide + 1));
    if (vertices > kMaxVerticesPerScene)
      node.fail(std::to_string(patches.size()) + " patches at " + std::to_string(perSide) + " segments a side make " +
                std::to_string(vertices) + " vertices, more than a scene may have; lower \"segments\"");
    return parametricMesh(std::move(name), std::move(patches), perSide);
  }
  if (source == "primitive") {
    if (pick) pick->fail("\"mesh\" picks a mesh inside a glTF \"file\"; a primitive has none");
    return readPrimitive(node.at("primitive"), std::move(name));
  }
  const JsonNode file = node.at("file");
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  const std::string extension = lowercaseExtension(*path);
  const bool gltf = isGltfFile(*path);
  if (!gltf && extension != ".obj")
    file.fail("unsupported mesh file type " + JsonNode::quoted(extension) + "; use .obj, .gltf or .glb");
  if (pick && !gltf) pick->fail("an OBJ file holds one mesh; \"mesh\" only picks among a glTF file's meshes");
  Result<Mesh> mesh =
      gltf ? importGltf(path.value(), pick ? readMeshSelector(*pick) : GltfMeshSelector{}, std::move(name))
           : importObj(path.value(), std::move(name));
  if (!mesh) file.fail(mesh.error());
  return std::move(mesh).value();
}

// A mesh entry: its source, then long edges split when "max_edge" asks for it.
Mesh readMesh(const JsonNode& node, const fs::path& baseDir, NameIndex& meshes) {
  node.expectObject({"name", "file", "mesh", "primitive", "bezier_patches", "bspline", "segments", "max_edge"});
  Mesh mesh = readMeshSource(node, baseDir, meshes.add(node.at("name")));
  const std::optional<JsonNode> maxEdge = node.find("max_edge");
  if (!maxEdge) return mesh;
  if (!mesh.patches.empty())
    maxEdge->fail("a parametric surface's grid is set by \"segments\", not split by \"max_edge\"; drop max_edge");
  std::optional<Mesh> split =
      subdivideLongEdges(mesh, static_cast<float>(maxEdge->positive()), kMaxVerticesPerScene / 3);
  if (!split)
    maxEdge->fail("splitting every edge longer than " + std::to_string(maxEdge->positive()) +
                  " m would make more than " + std::to_string(kMaxVerticesPerScene / 3) +
                  " triangles; use a larger max_edge");
  return std::move(split).value();
}

// Textures by the file and wrap mode that made them, so materials sharing an image decode it once.
struct TextureFiles {
  std::map<std::pair<fs::path, TextureWrap>, std::uint32_t> loaded;
  std::size_t texels = 0;
};

// "file.png" or {"file": "file.png", "wrap": "repeat" | "clamp" | "mirror"}: an image beside the scene.
std::uint32_t readTexture(const JsonNode& node, const fs::path& baseDir, Scene& scene, TextureFiles& files) {
  const JsonNode file = node.isString() ? node : node.at("file");
  TextureWrap wrap = TextureWrap::Repeat;
  if (!node.isString()) {
    node.expectObject({"file", "wrap"});
    if (const auto mode = node.find("wrap")) {
      if (mode->string() == "clamp") wrap = TextureWrap::ClampToEdge;
      else if (mode->string() == "mirror") wrap = TextureWrap::MirroredRepeat;
      else if (mode->string() != "repeat")
        mode->fail("unknown wrap " + JsonNode::quoted(mode->string()) + "; use repeat, clamp or mirror");
    }
  }
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  if (const auto known = files.loaded.find({*path, wrap}); known != files.loaded.end()) return known->second;
  Result<std::string> bytes = readBoundedFile(*path, kMaxAssetFileBytes);
  if (!bytes) file.fail(bytes.error());
  Result<Texture> texture = decodeTexture(*bytes, path->filename().string());
  if (!texture) file.fail(texture.error());
  if ((files.texels += texture->texelCount()) > kMaxTexelsPerScene)
    file.fail("the scene's textures hold more than " + std::to_string(kMaxTexelsPerScene) +
              " texels with this one; use smaller images");
  texture->wrapU = texture->wrapV = wrap;
  scene.textures.push_back(std::move(texture).value());
  return files.loaded[{*path, wrap}] = static_cast<std::uint32_t>(scene.textures.size() - 1);
}

// A material; "color" may be left out when a texture gives the colour (it then multiplies white).
Material readMaterial(const JsonNode& node, NameIndex& materials, const fs::path& baseDir, Scene& scene,
                      TextureFiles& textures) {
  node.expectObject({"name", "color", "unlit", "checker", "reflectivity", "texture"});
  Material material;
  material.name = materials.add(node.at("name"));
  const std::optional<JsonNode> texture = node.find("texture");
  if (texture) material.texture = readTexture(*texture, baseDir, scene, textures);
  material.baseColor = texture && !node.find("color") ? glm::vec3(1.0f) : readColor(node.at("color"));
  if (const auto unlit = node.find("unlit")) material.unlit = unlit->boolean();
  if (const auto reflectivity = node.find("reflectivity"))
    material.reflectivity = static_cast<float>(reflectivity->inRange(0.0, 1.0));
  if (const auto checker = node.find("checker")) {
    checker->expectObject({"color", "cells_per_unit"});
    material.checker = Checker{readColor(checker->at("color")), 1.0f};
    if (const auto cells = checker->find("cells_per_unit"))
      material.checker->cellsPerUnit = static_cast<float>(cells->positive());
  }
  return material;
}

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
  mirror.closed = closed ? closed->boolean() : !twin;
  if (!mirror.closed && !twin)
    node.fail(
        "an open mirror (\"closed\": false) needs \"closed_twin\": a closed mesh of the same surface for the "
        "reflection search");
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

// {"glTF material name": true | false, ...}: mirrors whatever their factors, or not.
std::map<std::string, bool> readMirrorMaterials(const JsonNode& node) {
  std::map<std::string, bool> materials;
  for (const auto& [name, mirror] : node.members(kMaxEntities)) materials[name] = mirror.boolean();
  return materials;
}

// {"name": "engine", "file": "engine.glb", "scene": N, "translation", "rotation", "scale"}: a glTF
// file's scene (its default, or "scene") as a group placed by the transform. Its objects are named
// "<name>/<object>", so animations and protocol overrides can move them one by one; its materials
// and textures come along; its cameras and lights do not (the scene file has its own).
void readInclude(const JsonNode& node, const fs::path& baseDir, Scene& scene, Names& names, TextureFiles& textures) {
  node.expectObject({"name", "file", "scene", "mirror_rule", "translation", "rotation", "scale"});
  const JsonNode nameNode = node.at("name");
  const std::string& group = nameNode.string();
  if (group.empty() || group.find('/') != std::string::npos)
    nameNode.fail("an include's name must be non-empty and without '/' (it prefixes its objects' names: \"" + group +
                  "/...\")");
  const JsonNode file = node.at("file");
  Result<fs::path> path = resolveInside(baseDir, file.string());
  if (!path) file.fail(path.error());
  if (!isGltfFile(*path))
    file.fail("an include is a glTF file (.gltf or .glb), got " + JsonNode::quoted(lowercaseExtension(*path)));
  GltfSceneChoice choice;
  if (const auto index = node.find("scene"))
    choice.scene = static_cast<std::size_t>(index->integer(0, std::numeric_limits<std::int32_t>::max()));
  if (const auto rule = node.find("mirror_rule")) {
    // {"metallic": at least, "roughness": at most, "materials": {"name": true | false}}
    rule->expectObject({"metallic", "roughness", "materials"});
    if (const auto metallic = rule->find("metallic")) choice.mirrors.minMetallic = metallic->inRange(0.0, 1.0);
    if (const auto roughness = rule->find("roughness")) choice.mirrors.maxRoughness = roughness->inRange(0.0, 1.0);
    if (const auto materials = rule->find("materials")) choice.mirrors.materials = readMirrorMaterials(*materials);
  }
  Result<ImportedGltfScene> imported = importGltfScene(*path, choice);
  if (!imported) file.fail(imported.error());
  Scene& included = imported->scene;
  for (const Texture& texture : included.textures)
    if ((textures.texels += texture.texelCount()) > kMaxTexelsPerScene)
      file.fail("the scene's textures hold more than " + std::to_string(kMaxTexelsPerScene) +
                " texels with this file's; use smaller images");
  const auto meshOffset = static_cast<std::uint32_t>(scene.meshes.size());
  const auto materialOffset = static_cast<std::uint32_t>(scene.materials.size());
  const auto textureOffset = static_cast<std::uint32_t>(scene.textures.size());
  std::move(included.meshes.begin(), included.meshes.end(), std::back_inserter(scene.meshes));
  std::move(included.textures.begin(), included.textures.end(), std::back_inserter(scene.textures));
  for (Material& material : included.materials) {
    if (material.texture) *material.texture += textureOffset;
    material.name = group + "/" + material.name;
    scene.materials.push_back(std::move(material));
  }
  const math::Transform placement = readTransform(node, math::Transform{});
  for (SceneObject& object : included.objects) {
    object.name = names.objects.add(group + "/" + object.name, nameNode);
    object.mesh += meshOffset;
    object.material += materialOffset;
    if (object.mirror && object.mirror->closedTwinMesh) *object.mirror->closedTwinMesh += meshOffset;
    object.transform = placement;  // the group's meshes are in its world space
    scene.objects.push_back(std::move(object));
  }
}

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

Scene readScene(const JsonNode& root, const fs::path& baseDir, std::string defaultName) {
  // The version comes first so a newer file fails on its version, not on keys this build does not know.
  const std::optional<JsonNode> version = root.find("specula_scene");
  if (!version) root.fail("missing \"specula_scene\": " + std::to_string(kSceneFormatVersion) + ", the format version");
  if (const std::int64_t number =
          version->integer(std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max());
      number != kSceneFormatVersion)
    version->fail("unsupported scene format version " + std::to_string(number) + "; this build reads version " +
                  std::to_string(kSceneFormatVersion));
  root.expectObject({"specula_scene", "name", "background", "ambient", "camera", "meshes", "materials", "objects",
                     "includes", "lights", "animations"});
  Scene scene;
  const std::optional<JsonNode> name = root.find("name");
  scene.name = name ? name->string() : std::move(defaultName);
  if (const auto background = root.find("background")) scene.background = readColor(*background);
  if (const auto ambient = root.find("ambient")) scene.ambient = readColor(*ambient);
  const JsonNode camera = root.at("camera");
  camera.expectObject({"eye", "target", "up", "fov"});
  scene.camera = readCamera(camera, math::Camera{});

  Names names;
  // A scene of included glTF files alone needs no meshes, materials or objects of its own.
  const std::optional<JsonNode> includes = root.find("includes");
  const auto entities = [&](std::string_view key) {
    const std::optional<JsonNode> list = root.find(key);
    if (!list && !includes) root.at(key);  // fails: the key is required
    return list ? list->array(includes ? 0 : 1, kMaxEntities) : std::vector<JsonNode>{};
  };
  std::size_t meshVertices = 0;
  for (const JsonNode& node : entities("meshes")) {
    scene.meshes.push_back(readMesh(node, baseDir, names.meshes));
    if ((meshVertices += scene.meshes.back().vertices.size()) > kMaxVerticesPerScene)
      node.fail("meshes hold " + std::to_string(meshVertices) + " vertices so far, more than the scene limit of " +
                std::to_string(kMaxVerticesPerScene));
  }
  TextureFiles textures;
  for (const JsonNode& node : entities("materials"))
    scene.materials.push_back(readMaterial(node, names.materials, baseDir, scene, textures));
  std::size_t vertices = 0, triangles = 0;
  for (const JsonNode& node : entities("objects")) {
    scene.objects.push_back(readObject(node, names));
    const Mesh& mesh = scene.meshes[scene.objects.back().mesh];
    if ((vertices += mesh.vertices.size()) > kMaxVerticesPerScene ||
        (triangles += mesh.triangleCount()) > kMaxTrianglesPerScene)
      node.fail("objects so far draw " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                " triangles, more than the scene limits of " + std::to_string(kMaxVerticesPerScene) + " and " +
                std::to_string(kMaxTrianglesPerScene));
  }
  if (includes) {
    for (const JsonNode& node : includes->array(1, kMaxIncludes)) readInclude(node, baseDir, scene, names, textures);
    if (scene.vertexCount() > kMaxVerticesPerScene || scene.triangleCount() > kMaxTrianglesPerScene)
      includes->fail("with its includes the scene draws " + std::to_string(scene.vertexCount()) + " vertices and " +
                     std::to_string(scene.triangleCount()) + " triangles, more than the limits of " +
                     std::to_string(kMaxVerticesPerScene) + " and " + std::to_string(kMaxTrianglesPerScene));
  }
  if (const auto lights = root.find("lights"))
    for (const JsonNode& node : lights->array(0, kMaxLights)) scene.lights.push_back(readLight(node));
  if (const auto animations = root.find("animations"))
    for (const JsonNode& node : animations->array(0, kMaxEntities))
      scene.animations.push_back(readAnimation(node, names, scene));
  return scene;
}

}  // namespace

Result<Scene> loadSceneFile(const fs::path& file) {
  Result<std::string> text = readBoundedFile(file, kMaxSceneFileBytes);
  if (!text) return Error{text.error()};
  return parseScene(text.value(), file.parent_path(), file.string());
}

Result<Scene> parseScene(std::string_view json, const fs::path& baseDir, std::string_view sourceName) {
  const std::string source(sourceName);
  if (json.size() > kMaxSceneFileBytes)
    return Error{source + ": " + std::to_string(json.size()) + " bytes, more than the limit of " +
                 std::to_string(kMaxSceneFileBytes)};
  Result<nlohmann::json> document = parseStrictJson(json);
  if (!document) return Error{source + ": " + document.error()};
  std::optional<Scene> scene;
  try {
    scene = readScene(JsonNode(document.value(), "$"), baseDir, fs::path(source).stem().string());
  } catch (const JsonNode::Failure& failure) {
    return Error{source + ": " + failure.message};
  }
  if (auto problem = sceneProblem(*scene)) return Error{source + ": " + *problem};
  return *std::move(scene);
}

}  // namespace specula::scene
