#include "scene/ObjImporter.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "scene/AssetFiles.h"
#include "scene/MeshNormals.h"
#include "scene/SceneChecks.h"

namespace specula::scene {

namespace {

// A face corner as the OBJ indexes it (0-based, -1 = absent); corners that agree share one vertex.
struct Corner {
  int position;
  int uv;
  int normal;
  bool operator==(const Corner&) const = default;
};

struct CornerHash {
  std::size_t operator()(const Corner& c) const {
    return std::hash<std::uint64_t>{}((static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.position)) << 32) ^
                                      (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.uv)) << 16) ^
                                      static_cast<std::uint32_t>(c.normal));
  }
};

// tinyobjloader reserves 8192 values per tag line ("t ..."), 360 KB each; tags mean nothing here, so drop them.
void commentOutTagLines(std::string& text) {
  bool lineStart = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      lineStart = true;
    } else if (lineStart && c != ' ' && c != '\t') {
      if (c == 't' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\t')) text[i] = '#';
      lineStart = false;
    }
  }
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Why `corner` (from face number `face`, 1-based like the file's own indices) cannot be used, if it cannot.
std::optional<std::string> cornerProblem(const Corner& corner, const tinyobj::attrib_t& attrib, std::size_t face) {
  const auto outOfRange = [&](const char* what, int index, std::size_t count) {
    return "face " + std::to_string(face) + " refers to " + what + " " + std::to_string(index + 1) +
           ", but the file defines " + std::to_string(count);
  };
  const std::size_t positions = attrib.vertices.size() / 3, uvs = attrib.texcoords.size() / 2,
                    normals = attrib.normals.size() / 3;
  if (corner.position < 0 || static_cast<std::size_t>(corner.position) >= positions)
    return outOfRange("vertex", corner.position, positions);
  if (corner.uv < -1 || (corner.uv >= 0 && static_cast<std::size_t>(corner.uv) >= uvs))
    return outOfRange("texture coordinate", corner.uv, uvs);
  if (corner.normal < -1 || (corner.normal >= 0 && static_cast<std::size_t>(corner.normal) >= normals))
    return outOfRange("normal", corner.normal, normals);
  return std::nullopt;
}

// The vertex for a valid corner, or why the numbers it points at are unusable.
Result<Vertex> cornerVertex(const Corner& corner, const tinyobj::attrib_t& attrib) {
  const auto p = static_cast<std::size_t>(corner.position);
  Vertex vertex;
  vertex.position = {attrib.vertices[3 * p], attrib.vertices[3 * p + 1], attrib.vertices[3 * p + 2]};
  if (!finite(vertex.position)) return Error{"vertex " + std::to_string(p + 1) + " has a non-finite coordinate"};
  if (corner.uv >= 0) {
    const auto t = static_cast<std::size_t>(corner.uv);
    vertex.uv = {attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]};
    if (!std::isfinite(vertex.uv.x) || !std::isfinite(vertex.uv.y))
      return Error{"texture coordinate " + std::to_string(t + 1) + " is not finite"};
  }
  if (corner.normal >= 0) {
    const auto n = static_cast<std::size_t>(corner.normal);
    const glm::vec3 normal{attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]};
    const float length = glm::length(normal);
    if (!(length > 0.0f) || !std::isfinite(length))
      return Error{"normal " + std::to_string(n + 1) + " is zero or not finite"};
    vertex.normal = normal / length;
  }
  return vertex;
}

Result<Mesh> buildMesh(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes, std::string name) {
  Mesh mesh;
  mesh.name = std::move(name);
  std::unordered_map<Corner, std::uint32_t, CornerHash> shared;
  bool everyCornerHasNormal = true;
  std::size_t face = 0;
  std::vector<std::uint32_t> polygon;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t first = 0;
    for (const unsigned char count : shape.mesh.num_face_vertices) {
      ++face;
      // tinyobjloader stores corner counts in a byte, so a longer face wraps around and misaligns the rest.
      if (count < 3 || first + count > shape.mesh.indices.size())
        return Error{"face " + std::to_string(face) + " has more than 255 corners; split it into smaller polygons"};
      if (mesh.triangleCount() + count - 2u > kMaxTrianglesPerScene)
        return Error{"more than " + std::to_string(kMaxTrianglesPerScene) + " triangles, the limit per scene"};
      polygon.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const tinyobj::index_t& index = shape.mesh.indices[first + k];
        const Corner corner{index.vertex_index, index.texcoord_index, index.normal_index};
        if (auto problem = cornerProblem(corner, attrib, face)) return Error{*problem};
        const auto [it, added] = shared.emplace(corner, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (added) {
          if (mesh.vertices.size() == kMaxVerticesPerScene)
            return Error{"more than " + std::to_string(kMaxVerticesPerScene) + " vertices, the limit per scene"};
          Result<Vertex> vertex = cornerVertex(corner, attrib);
          if (!vertex) return Error{vertex.error()};
          mesh.vertices.push_back(vertex.value());
        }
        everyCornerHasNormal = everyCornerHasNormal && corner.normal >= 0;
        polygon.push_back(it->second);
      }
      // A fan is exact for the convex polygons exporters write; OBJ gives no better hint for concave ones.
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k], polygon[k + 1]});
      first += count;
    }
    if (first != shape.mesh.indices.size())
      return Error{"a face has more than 255 corners (tinyobjloader's limit); split it into smaller polygons"};
  }
  if (mesh.indices.empty()) return Error{"has no faces (\"f\" lines), so there is no mesh to import"};
  if (!everyCornerHasNormal) computeSmoothNormals(mesh);
  return mesh;
}

}  // namespace

Result<Mesh> importObj(const std::filesystem::path& file, std::string meshName) {
  Result<std::string> text = readBoundedFile(file, kMaxAssetFileBytes);
  if (!text) return Error{text.error()};
  const std::string where = file.string() + ": ";
  if (text->empty()) return Error{where + "empty file; an OBJ mesh needs \"v\" and \"f\" lines"};
  commentOutTagLines(text.value());
  std::istringstream stream(std::move(text.value()));
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, error;
  try {
    // No material reader: "mtllib" could name any file on disk, and materials come from the scene file.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, nullptr, /*triangulate=*/false))
      return Error{where + "not a valid OBJ file: " + oneLine(error)};
  } catch (const std::exception& e) {
    return Error{where + "cannot be parsed: " + e.what()};
  }
  Result<Mesh> mesh = buildMesh(attrib, shapes, std::move(meshName));
  if (!mesh) return Error{where + mesh.error()};
  return mesh;
}

}  // namespace specula::scene
