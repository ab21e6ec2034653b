#pragma once
// A mesh's hierarchy on the GPU (shaders/common/triangle-bvh.glsl), for casting reflected rays against
// it: a mirror's own mesh where it may see itself, an object's in a ray-cast part.
#include <cstdint>
#include <optional>
#include <vector>

#include "gl/GlObject.h"

namespace specula::passes {

struct MeshBvh {
  gl::GlBuffer nodes, triangles;
  float minDistance = 0.0f;  // object space: hits nearer the ray's start are the surface it starts on
  // For a mesh that changes shape (GpuDeformation refits the boxes, keeping the tree): its node indices
  // level by level, deepest first, and each level's range in that list.
  struct Level {
    std::uint32_t first = 0, size = 0;
  };
  std::optional<gl::GlBuffer> levelOrder;
  std::vector<Level> levels;
  std::uint64_t shape = 0;  // which of the mesh's shapes (GpuDeformation counts them) the boxes fit
};

}  // namespace specula::passes
