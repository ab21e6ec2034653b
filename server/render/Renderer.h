#pragma once
// Runs the passes a scene needs for one view and reads the frame back.
// Owns GL resources: create, use and destroy it on the thread where its context is current.
#include <cstdint>
#include <memory>
#include <vector>

#include "base/Result.h"
#include "gl/GlContext.h"
#include "gl/GpuMeshes.h"
#include "passes/Pass.h"
#include "render/FrameTimings.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

namespace specula::render {

struct RenderedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // sRGB, tightly packed, row 0 at the top
  FrameTimings timings;
};

class Renderer {
 public:
  // Uploads the scene's meshes and builds every pass's program; fails on shader errors.
  static Result<std::unique_ptr<Renderer>> create(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene);
  ~Renderer();

  // Renders the scene at `pose` (its camera included) into a width × height frame.
  Result<RenderedFrame> render(const scene::ScenePose& pose, int width, int height);

  const scene::Scene& scene() const { return *scene_; }

 private:
  Renderer(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene);
  // Near and far distances that enclose the whole posed scene as seen from the pose's camera.
  std::pair<float, float> clipRange(const scene::ScenePose& pose) const;

  gl::GlContext& context_;
  std::shared_ptr<const scene::Scene> scene_;
  gl::GpuMeshes meshes_;
  std::vector<std::pair<glm::vec3, glm::vec3>> meshBounds_;  // object-space AABB per mesh
  std::vector<std::unique_ptr<passes::Pass>> passes_;
};

}  // namespace specula::render
