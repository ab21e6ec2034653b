#pragma once
// Small helpers every built-in scene generator shares: colours, materials, placing objects.
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace specula::scene::builtin {

// An sRGB design colour written 0xRRGGBB, converted to the linear RGB that materials hold.
glm::vec3 srgbHex(std::uint32_t rgb);

Material matte(std::string name, std::uint32_t rgb);
Material emissive(std::string name, std::uint32_t rgb);  // unlit: shown exactly as stored
Material mirror(std::string name, std::uint32_t rgb, float reflectivity);
// A perfect mirror: no colour of its own (black, unlit), so its pixels are reflection only.
Material perfectMirror(std::string name);
// Checker over uv: cells where floor(u·cells) + floor(v·cells) is even take `even`.
Material checker(std::string name, std::uint32_t even, std::uint32_t odd, float cellsPerUnit, bool unlit);

// `count` points on the ellipse centre + radii·(cos a, sin a) for a from `fromDegrees` to `toDegrees`:
// profile arcs for lathe() and paths for tubes.
std::vector<glm::vec2> ellipseArc(const glm::vec2& centre, const glm::vec2& radii, float fromDegrees, float toDegrees,
                                  int count);

// Rotation about +y by `degrees` (counter-clockwise seen from above): turns +x towards −z.
glm::quat yaw(float degrees);
math::Transform placed(const glm::vec3& translation, float yawDegrees = 0.0f, const glm::vec3& scale = glm::vec3(1.0f));

// A directional light shining from `towardsLight` (need not be unit) with white colour.
Light sunLight(const glm::vec3& towardsLight, float intensity);

// Append to the scene and return the new element's index, so generators can refer to it.
std::uint32_t addMesh(Scene& scene, Mesh mesh);
std::uint32_t addMaterial(Scene& scene, Material material);
std::uint32_t addObject(Scene& scene, std::string name, std::uint32_t mesh, std::uint32_t material,
                        const math::Transform& transform = {});
// Adds a closed convex mirror whose mesh approximates a sphere of `radius` about the object origin,
// with that exact sphere attached for the exact solvers.
std::uint32_t addSphereMirror(Scene& scene, std::string name, std::uint32_t mesh, std::uint32_t material, float radius,
                              const math::Transform& transform);

}  // namespace specula::scene::builtin
