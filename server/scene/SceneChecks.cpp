#include "scene/SceneChecks.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/Deformation.h"

namespace specula::scene {

namespace {

bool finite(float v) { return std::isfinite(v); }
bool finite(const glm::vec2& v) { return finite(v.x) && finite(v.y); }
bool finite(const glm::vec3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }
bool finite(const glm::quat& q) { return finite(q.x) && finite(q.y) && finite(q.z) && finite(q.w); }
bool finite(const math::Transform& t) { return finite(t.translation) && finite(t.rotation) && finite(t.scale); }
bool isUnit(const glm::vec3& v) { return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f; }
bool inUnitRange(const glm::vec3& c) { return finite(c) && glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))); }

std::optional<std::string> meshProblem(const Mesh& mesh) {
  const std::string where = "mesh '" + mesh.name + "': ";
  if (mesh.indices.size() % 3 != 0) return where + "index count is not a multiple of 3";
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.vertices.size())
      return where + "index " + std::to_string(i) + " refers to vertex " + std::to_string(mesh.indices[i]) + " of " +
             std::to_string(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    if (!finite(v.position) || !finite(v.normal) || !finite(v.uv))
      return where + "vertex " + std::to_string(i) + " has a non-finite value";
  }
  // The renderer finds a triangle's patch from its index: the grid must be exactly parametricMesh's.
  if (!mesh.patches.empty() &&
      (mesh.patchSegments < 1 ||
       mesh.triangleCount() !=
           mesh.patches.size() * 2 * static_cast<std::size_t>(mesh.patchSegments * mesh.patchSegments)))
    return where + "its triangles are not the uniform grid of its " + std::to_string(mesh.patches.size()) +
           " patches; build it with scene::parametricMesh";
  return std::nullopt;
}

// An extrusion mirror's drawn mesh must be the extrusion's side: a cap would be solved as if it were
// side, and a profile that is not the mesh's would put every reflection point off the drawn surface.
std::optional<std::string> extrusionMeshProblem(const Mesh& mesh, const math::Extrusion& extrusion) {
  constexpr double kOffProfile = 0.02;  // of the radius: a faceted mesh's vertices lie on the curve
  constexpr double kAlongSine = 0.1;    // normals within about 6° of square to the direction
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    const glm::dvec3 offset = glm::dvec3(v.position) - extrusion.axisPoint;
    const glm::dvec2 unit(glm::dot(offset, extrusion.u) / extrusion.radii.x,
                          glm::dot(offset, extrusion.v) / extrusion.radii.y);
    if (std::abs(glm::dot(glm::normalize(glm::dvec3(v.normal)), extrusion.direction)) > kAlongSine)
      return "vertex " + std::to_string(i) + " of mesh '" + mesh.name +
             "' has a normal along the extrusion (a cap?): an extrusion mirror's mesh is its side only; make caps "
             "another "
             "object, and the mirror open with a closed twin";
    const double off = std::abs(glm::length(unit) - 1.0);
    if (off > kOffProfile)
      return "vertex " + std::to_string(i) + " of mesh '" + mesh.name + "' lies " + std::to_string(off) +
             " of a radius off the declared profile: the extrusion must describe the mirror's mesh (its axis point, "
             "direction and radii)";
  }
  return std::nullopt;
}

// The levels must be the chain decodeTexture builds: the GPU uploads them as they are.
std::optional<std::string> textureProblem(const Texture& texture) {
  if (texture.levels.empty()) return "has no texels";
  for (std::size_t i = 0; i < texture.levels.size(); ++i) {
    const TextureLevel& level = texture.levels[i];
    const int expectedWidth = i == 0 ? level.width : std::max(1, texture.levels[i - 1].width / 2);
    const int expectedHeight = i == 0 ? level.height : std::max(1, texture.levels[i - 1].height / 2);
    if (level.width < 1 || level.height < 1 || level.width > kMaxTextureSide || level.height > kMaxTextureSide ||
        level.width != expectedWidth || level.height != expectedHeight ||
        level.rgba.size() != static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height) * 4)
      return "level " + std::to_string(i) + " is not the mip chain's; build textures with scene::decodeTexture";
  }
  if (texture.levels.back().width != 1 || texture.levels.back().height != 1) return "its mip chain stops before 1x1";
  return std::nullopt;
}

std::optional<std::string> transformProblem(const math::Transform& t) {
  if (!finite(t)) return "transform has a non-finite value";
  if (std::abs(glm::length(t.rotation) - 1.0f) > 1e-3f) return "rotation quaternion is not unit length";
  if (glm::any(glm::equal(t.scale, glm::vec3(0.0f)))) return "scale has a zero component";
  return std::nullopt;
}

}  // namespace

std::optional<std::string> sceneProblem(const Scene& scene) {
  if (scene.vertexCount() > kMaxVerticesPerScene)
    return "scene has " + std::to_string(scene.vertexCount()) + " vertices, more than the limit of " +
           std::to_string(kMaxVerticesPerScene);
  if (scene.triangleCount() > kMaxTrianglesPerScene)
    return "scene has " + std::to_string(scene.triangleCount()) + " triangles, more than the limit of " +
           std::to_string(kMaxTrianglesPerScene);
  for (const Mesh& mesh : scene.meshes)
    if (auto problem = meshProblem(mesh)) return problem;
  for (const Material& m : scene.materials) {
    if (!inUnitRange(m.baseColor)) return "material '" + m.name + "': base colour must be finite and non-negative";
    if (!(m.reflectivity >= 0.0f && m.reflectivity <= 1.0f))
      return "material '" + m.name + "': reflectivity must lie in [0, 1]";
    if (m.checker &&
        (!inUnitRange(m.checker->oddColor) || !(m.checker->cellsPerUnit > 0.0f) || !finite(m.checker->cellsPerUnit)))
      return "material '" + m.name + "': checker needs a finite colour and cellsPerUnit > 0";
    if (m.texture && *m.texture >= scene.textures.size())
      return "material '" + m.name + "': texture index out of range";
  }
  std::size_t texels = 0;
  for (const Texture& texture : scene.textures) {
    if (auto problem = textureProblem(texture)) return "texture '" + texture.name + "': " + *problem;
    texels += texture.texelCount();
  }
  if (texels > kMaxTexelsPerScene)
    return "the textures hold " + std::to_string(texels) + " texels with their mip chains, more than the limit of " +
           std::to_string(kMaxTexelsPerScene) + " a scene; use smaller images";
  std::set<std::string> names;
  for (const SceneObject& o : scene.objects) {
    const std::string where = "object '" + o.name + "': ";
    if (!names.insert(o.name).second) return where + "name is used twice";
    if (o.mesh >= scene.meshes.size()) return where + "mesh index out of range";
    if (o.material >= scene.materials.size()) return where + "material index out of range";
    if (auto problem = transformProblem(o.transform)) return where + *problem;
    if (o.mirror) {
      if (o.mirror->closed && o.mirror->closedTwinMesh)
        return where + "a closed mirror must not have a closed twin mesh";
      if (o.mirror->closedTwinMesh && *o.mirror->closedTwinMesh >= scene.meshes.size())
        return where + "closed twin mesh index out of range";
      if (o.mirror->analytic && (!finite(o.mirror->analytic->center) ||
                                 !glm::all(glm::greaterThan(o.mirror->analytic->radii, glm::vec3(0.0f))) ||
                                 !finite(o.mirror->analytic->radii)))
        return where + "analytic shape needs a finite centre and positive radii";
      if (const auto& e = o.mirror->extrusion) {
        const bool orthonormal =
            std::abs(glm::dot(e->u, e->v)) < 1e-6 && std::abs(glm::dot(e->u, e->direction)) < 1e-6 &&
            std::abs(glm::dot(e->v, e->direction)) < 1e-6 && std::abs(glm::length(e->u) - 1.0) < 1e-6 &&
            std::abs(glm::length(e->v) - 1.0) < 1e-6 && std::abs(glm::length(e->direction) - 1.0) < 1e-6;
        if (!finite(glm::vec3(e->axisPoint)) || !orthonormal || !(e->radii.x > 0.0 && e->radii.y > 0.0) ||
            !finite(glm::vec3(e->radii, 0.0)))
          return where + "extrusion needs a finite axis point, an orthonormal frame and positive radii";
        if (o.mirror->analytic) return where + "a mirror is an analytic quadric or an extrusion, not both";
        if (o.mirror->curvature != MirrorCurvature::Convex) return where + "an extrusion mirror must be convex";
        if (auto problem = extrusionMeshProblem(scene.meshes[o.mesh], *e)) return where + *problem;
      }
    }
  }
  if (scene.lights.size() > kMaxLights) return "more than " + std::to_string(kMaxLights) + " lights";
  for (const Light& l : scene.lights) {
    if (!inUnitRange(l.color) || !finite(l.intensity) || l.intensity < 0.0f)
      return "light has a bad colour or intensity";
    if (l.kind == Light::Kind::Directional ? !isUnit(l.vector) : !finite(l.vector))
      return "light direction must be a unit vector (position finite)";
  }
  if (!inUnitRange(scene.ambient) || !inUnitRange(scene.background))
    return "ambient and background must be finite, non-negative";
  if ((scene.environment.kind == EnvironmentKind::Image) !=
      (scene.environment.image && *scene.environment.image < scene.textures.size()))
    return "an environment image must name one of the scene's textures, and only an image environment names one";
  if (auto problem = math::cameraProblem(scene.camera)) return "default " + *problem;

  for (std::size_t a = 0; a < scene.animations.size(); ++a) {
    const Animation& animation = scene.animations[a];
    const std::string where = "animation " + std::to_string(a) + ": ";
    if (animation.object && *animation.object >= scene.objects.size()) return where + "object index out of range";
    auto keysIncrease = [](const auto& keys) {
      for (std::size_t i = 0; i < keys.size(); ++i)
        if (!std::isfinite(keys[i].time) || (i > 0 && !(keys[i].time > keys[i - 1].time))) return false;
      return !keys.empty();
    };
    if (auto* spin = std::get_if<Spin>(&animation.motion)) {
      if (!animation.object) return where + "spin applies to objects, not the camera";
      if (!isUnit(spin->axis) || !std::isfinite(spin->degreesPerSecond))
        return where + "spin needs a unit axis and a finite rate";
    } else if (auto* orbit = std::get_if<Orbit>(&animation.motion)) {
      if (!isUnit(orbit->axis) || !finite(orbit->center) || !std::isfinite(orbit->degreesPerSecond))
        return where + "orbit needs a finite centre, a unit axis and a finite rate";
    } else if (auto* path = std::get_if<TransformPath>(&animation.motion)) {
      if (!animation.object) return where + "a transform path applies to objects; use a camera path for the camera";
      if (!keysIncrease(path->keys)) return where + "keys must be non-empty with finite, strictly increasing times";
      for (const TransformKey& key : path->keys)
        if (auto problem = transformProblem(key.transform)) return where + *problem;
    } else if (auto* cameraPath = std::get_if<CameraPath>(&animation.motion)) {
      if (animation.object) return where + "a camera path applies to the camera only";
      if (!keysIncrease(cameraPath->keys))
        return where + "keys must be non-empty with finite, strictly increasing times";
      for (const CameraKey& key : cameraPath->keys)
        if (auto problem = math::cameraProblem(key.camera)) return where + *problem;
    }
  }
  if (auto problem = rigProblem(scene.rig, scene.objects.size())) return problem;
  std::vector<std::size_t> jointCount(scene.meshes.size(), 0);
  for (const SkinnedObject& skinned : scene.rig.skinned) {
    const SceneObject& object = scene.objects[skinned.object];
    jointCount[object.mesh] = scene.rig.skins[skinned.skin].joints.size();
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    if (auto problem = deformationProblem(scene.meshes[m], jointCount[m])) return problem;
  std::vector<std::size_t> users(scene.meshes.size(), 0);
  for (const SceneObject& object : scene.objects) ++users[object.mesh];
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    // The GPU writes a deforming object's shape into its mesh, which no other object may share.
    if (deforms(scene, o) && users[scene.objects[o].mesh] > 1)
      return "object '" + scene.objects[o].name + "' deforms a mesh other objects use too; give it its own";
    const std::optional<MirrorInfo>& mirror = scene.objects[o].mirror;
    // Those describe the rest shape only.
    if (mirror && (mirror->analytic || mirror->extrusion || mirror->closedTwinMesh) && deforms(scene, o))
      return "mirror '" + scene.objects[o].name +
             "' changes shape: it cannot declare an analytic shape, an extrusion or a closed twin";
  }
  for (const MorphedObject& morphed : scene.rig.morphed) {
    const SceneObject& object = scene.objects[morphed.object];
    if (morphed.restWeights.size() != scene.meshes[object.mesh].morphTargets.size())
      return "object '" + object.name + "' needs one rest weight per morph target of its mesh";
  }
  return std::nullopt;
}

}  // namespace specula::scene
