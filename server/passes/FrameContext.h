#pragma once
// What every pass of one frame sees: the GL context, the scene at this instant, the view, the target.
#include <glm/glm.hpp>

#include "gl/GlApi.h"
#include "gl/GpuMeshes.h"
#include "gl/RenderTarget.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::passes {

struct FrameContext {
  const gl::GlApi& gl;
  const scene::Scene& scene;
  const scene::ScenePose& pose;
  const gl::GpuMeshes& meshes;
  glm::mat4 worldToClip;  // projection × view for pose.camera and the target's aspect
  const gl::RenderTarget& target;
};

}  // namespace specula::passes
