#include "scene/file/FileMeshes.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/Result.h"
#include "scene/AssetFiles.h"
#include "scene/GltfImporter.h"
#include "scene/MeshSubdivision.h"
#include "scene/ObjImporter.h"
#include "scene/ParametricMesh.h"
#include "scene/SceneChecks.h"
#include "scene/file/FilePrimitives.h"
#include "scene/file/FileSurfaces.h"

namespace specula::scene::file {

namespace {

namespace fs = std::filesystem;

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

}  // namespace

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

}  // namespace specula::scene::file
