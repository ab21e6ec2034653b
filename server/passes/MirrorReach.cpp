#include "passes/MirrorReach.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/Transform.h"

namespace specula::passes {

namespace {

// Whether a transform keeps angles (rotation, translation, one scale), so normal cones stay cones.
bool keepsAngles(const glm::mat4& transform) {
  const float x = glm::length(glm::vec3(transform[0])), y = glm::length(glm::vec3(transform[1])),
              z = glm::length(glm::vec3(transform[2]));
  const float tolerance = 1e-4f * std::max({x, y, z});
  return std::abs(x - y) <= tolerance && std::abs(y - z) <= tolerance;
}

float smallestScale(const glm::mat4& transform) {
  return std::min({glm::length(glm::vec3(transform[0])), glm::length(glm::vec3(transform[1])),
                   glm::length(glm::vec3(transform[2]))});
}

// Whether the largest value of (P − S)·N over P in the object's sphere, S on the part and N in the
// normal cone is at most 0: the object is behind every tangent plane of the part. `partDepth` bounds
// (S − partCentre)·N over the part and the cone (at most the part's radius; 0 for a flat part).
bool behindEveryTangentPlane(const glm::vec3& partCentre, float partDepth, const glm::vec3& axis, float cosine,
                             const glm::vec3& objectCentre, float objectRadius) {
  const glm::vec3 offset = objectCentre - partCentre;
  const float distance = glm::length(offset);
  float largest = distance;  // N along the offset, if the cone holds that direction
  if (distance > 0.0f) {
    const float toAxis = std::acos(std::clamp(glm::dot(offset / distance, axis), -1.0f, 1.0f));
    const float halfAngle = std::acos(std::clamp(cosine, -1.0f, 1.0f));
    largest = distance * std::cos(std::max(0.0f, toAxis - halfAngle));
  }
  return largest + objectRadius + partDepth <= 0.0f;
}

// Whether every point of the object's sphere lies behind the ball as seen from the eye: inside the
// ball's cone from the eye and farther than its centre (beyond where any line of the cone meets it).
bool inShadowOf(const Ball& ball, const glm::vec3& eye, const glm::vec3& objectCentre, float objectRadius) {
  const glm::vec3 toBall = ball.centre - eye;
  const float ballDistance = glm::length(toBall);
  if (ballDistance <= ball.radius) return false;  // the eye is inside the ball
  const glm::vec3 toObject = objectCentre - eye;
  const float objectDistance = glm::length(toObject);
  if (objectDistance - objectRadius < ballDistance) return false;
  const float coneHalfAngle = std::asin(ball.radius / ballDistance);
  const float offAxis = std::acos(std::clamp(glm::dot(toObject / objectDistance, toBall / ballDistance), -1.0f, 1.0f));
  const float objectHalfAngle = std::asin(std::min(1.0f, objectRadius / objectDistance));
  return offAxis + objectHalfAngle < coneHalfAngle;
}

// Whether the sphere lies behind every tangent plane of the part placed by `mirrorToWorld`.
bool behindThePart(const MirrorReach& reach, const glm::mat4& mirrorToWorld, const glm::vec3& centre, float radius) {
  if (reach.normalCosine <= 0.0f || !keepsAngles(mirrorToWorld)) return false;
  const glm::vec3 axis = glm::normalize(math::normalMatrix(mirrorToWorld) * reach.normalAxis);
  // The part's box reaches |axis|·halfExtent along the axis; a normal tilted within the cone adds at
  // most sin(half angle) times the box's half diagonal (object space, then the transform's one scale).
  const glm::vec3 halfExtent = 0.5f * (reach.bounds.high - reach.bounds.low);
  const float sine = std::sqrt(std::max(0.0f, 1.0f - reach.normalCosine * reach.normalCosine));
  const float scale = std::max({glm::length(glm::vec3(mirrorToWorld[0])), glm::length(glm::vec3(mirrorToWorld[1])),
                                glm::length(glm::vec3(mirrorToWorld[2]))});
  const float depth = scale * std::min(glm::length(halfExtent), glm::dot(glm::abs(reach.normalAxis), halfExtent) +
                                                                    sine * glm::length(halfExtent));
  const glm::vec3 partCentre(mirrorToWorld * glm::vec4(reach.bounds.center(), 1.0f));
  return behindEveryTangentPlane(partCentre, depth, axis, reach.normalCosine, centre, radius);
}

}  // namespace

MirrorReach MirrorReach::ofMeshPart(const scene::Mesh& mesh, const scene::MirrorParts& parts, std::size_t part,
                                    bool closedConvex) {
  MirrorReach reach;
  glm::vec3 normalSum(0.0f);
  const auto inPart = [&](std::size_t triangle) {
    return parts.triangleParts.empty() || parts.triangleParts[triangle] == part;
  };
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!inPart(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const scene::Vertex& v = mesh.vertices[mesh.indices[3 * t + k]];
      reach.bounds.add(v.position);
      normalSum += v.normal;
    }
  }
  // Per edge, the radius of the circle through its corners with their normals' turn: chord / (2 sin(turn / 2)).
  float largestRadius = 0.0f;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!inPart(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const scene::Vertex& a = mesh.vertices[mesh.indices[3 * t + k]];
      const scene::Vertex& b = mesh.vertices[mesh.indices[3 * t + (k + 1) % 3]];
      const float chord = glm::length(a.position - b.position);
      if (chord <= 0.0f) continue;
      const float halfTurnSine = 0.5f * glm::length(glm::normalize(a.normal) - glm::normalize(b.normal));
      largestRadius = halfTurnSine > 1e-6f ? std::max(largestRadius, chord / (2.0f * halfTurnSine))
                                           : std::numeric_limits<float>::infinity();
    }
  }
  if (largestRadius > 0.0f) reach.largestCurvatureRadius = largestRadius;
  if (glm::length(normalSum) > 1e-6f) {
    reach.normalAxis = glm::normalize(normalSum);
    reach.normalCosine = 1.0f;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
      if (inPart(t))
        for (int k = 0; k < 3; ++k)
          reach.normalCosine =
              std::min(reach.normalCosine, glm::dot(mesh.vertices[mesh.indices[3 * t + k]].normal, reach.normalAxis));
  }
  if (closedConvex && !reach.bounds.empty()) {
    // The surface's area-weighted centroid (inside a convex body; duplicated seam vertices do not
    // pull it), and its distance to the nearest face plane (faces oriented outward by their vertex
    // normals); no ball when it is not inside every face.
    glm::dvec3 weighted(0.0);
    double area = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const glm::dvec3 a(mesh.vertices[mesh.indices[3 * t]].position),
          b(mesh.vertices[mesh.indices[3 * t + 1]].position), c(mesh.vertices[mesh.indices[3 * t + 2]].position);
      const double triangleArea = 0.5 * glm::length(glm::cross(b - a, c - a));
      weighted += triangleArea * (a + b + c) / 3.0;
      area += triangleArea;
    }
    const glm::vec3 centre(area > 0.0 ? weighted / area : glm::dvec3(reach.bounds.center()));
    float radius = std::numeric_limits<float>::max();
    for (std::size_t t = 0; t < mesh.triangleCount() && radius > 0.0f; ++t) {
      const scene::Vertex& a = mesh.vertices[mesh.indices[3 * t]];
      const scene::Vertex& b = mesh.vertices[mesh.indices[3 * t + 1]];
      const scene::Vertex& c = mesh.vertices[mesh.indices[3 * t + 2]];
      glm::vec3 normal = glm::cross(b.position - a.position, c.position - a.position);
      const float length = glm::length(normal);
      if (length <= 0.0f) continue;  // a degenerate face bounds nothing
      normal /= length;
      if (glm::dot(normal, a.normal + b.normal + c.normal) < 0.0f) normal = -normal;
      radius = std::min(radius, glm::dot(a.position - centre, normal));
    }
    if (radius > 0.0f && radius < std::numeric_limits<float>::max()) reach.inscribed = Ball{centre, radius};
  }
  return reach;
}

MirrorReach MirrorReach::ofQuadric(const scene::AnalyticShape& shape) {
  MirrorReach reach;
  reach.bounds.add(shape.center - shape.radii);
  reach.bounds.add(shape.center + shape.radii);
  const float smallest = std::min({shape.radii.x, shape.radii.y, shape.radii.z});
  const float largest = std::max({shape.radii.x, shape.radii.y, shape.radii.z});
  reach.inscribed = Ball{shape.center, smallest};
  reach.largestCurvatureRadius = largest * largest / smallest;  // an ellipsoid's flattest point
  return reach;
}

float worldCurvatureRadius(const MirrorReach& reach, const glm::mat4& mirrorToWorld) {
  if (!keepsAngles(mirrorToWorld)) return std::numeric_limits<float>::infinity();
  return reach.largestCurvatureRadius * glm::length(glm::vec3(mirrorToWorld[0]));
}

bool canAppearIn(const MirrorReach& reach, const glm::mat4& mirrorToWorld, const math::Bounds& object,
                 const glm::vec3& eye) {
  if (object.empty() || reach.bounds.empty()) return true;
  const glm::vec3 objectCentre = object.center();
  const float objectRadius = object.radius();
  if (behindThePart(reach, mirrorToWorld, objectCentre, objectRadius)) return false;
  if (reach.inscribed) {
    const Ball ball{glm::vec3(mirrorToWorld * glm::vec4(reach.inscribed->centre, 1.0f)),
                    reach.inscribed->radius * smallestScale(mirrorToWorld)};
    if (inShadowOf(ball, eye, objectCentre, objectRadius)) return false;
  }
  return true;
}

bool facesEye(const MirrorReach& reach, const glm::mat4& mirrorToWorld, const glm::vec3& eye) {
  return reach.bounds.empty() || !behindThePart(reach, mirrorToWorld, eye, 0.0f);
}

}  // namespace specula::passes
