#pragma once
// A mirror mesh split into parts of one curvature each (Ofek & Rappoport 1998 §6; Szabo 2013 §6):
// on a convex part a vertex has at most one reflection point, so the reflection-point search runs
// once per part and each part draws its own reflection. CPU only; computed once per mesh.
#include <cstdint>
#include <vector>

#include "scene/Mesh.h"
#include "scene/MirrorInfo.h"

namespace specula::scene {

enum class SurfaceKind { Convex, Concave, Saddle };

struct MirrorPart {
  SurfaceKind kind = SurfaceKind::Convex;
  std::uint32_t triangles = 0;
};

struct MirrorParts {
  // At most this many parts per mirror: beyond it the smallest merge into a neighbour (or into the
  // largest part), and a vertex may then have more images in one part than the search draws.
  static constexpr std::size_t kMaxParts = 8;

  std::vector<MirrorPart> parts;            // at least one
  std::vector<std::uint8_t> triangleParts;  // part of each triangle; empty when there is one part

  // Whether a reflected ray leaving this mirror can never meet the mirror again: one convex part of
  // a closed mesh, smoothly connected.
  bool cannotSeeItself(bool closed) const {
    return closed && parts.size() == 1 && parts[0].kind == SurfaceKind::Convex;
  }

  // `convex` and `concave` declare the whole mesh one part of that kind (the user's word is kept);
  // `mixed` classifies every triangle by the curvature of its vertex normals (convex, concave or
  // saddle; flat ones join a neighbour), groups smoothly connected triangles of one class (positions
  // welded, normals continuous: a crease or a uv-free split starts a new part) and merges parts
  // under 5 % of the mesh's area into a neighbour.
  static MirrorParts of(const Mesh& mesh, MirrorCurvature curvature);
};

}  // namespace specula::scene
