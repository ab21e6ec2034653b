#include "render/Renderer.h"

#include <chrono>
#include <limits>

#include "gl/GlObject.h"
#include "gl/RenderTarget.h"
#include "math/Camera.h"
#include "passes/ScenePass.h"

namespace specula::render {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Nearest clip distance as a share of the far one when the eye is inside the scene's bounds:
// keeps 24-bit depth precise to ~1e-4 of the far distance.
constexpr float kNearFarRatio = 1.0f / 2000.0f;

}  // namespace

Renderer::Renderer(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene)
    : context_(context), scene_(std::move(scene)), meshes_(context.api(), scene_->meshes) {
  for (const scene::Mesh& mesh : scene_->meshes) {
    glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    for (const scene::Vertex& v : mesh.vertices) {
      low = glm::min(low, v.position);
      high = glm::max(high, v.position);
    }
    meshBounds_.emplace_back(low, high);
  }
}

Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(gl::GlContext& context, std::shared_ptr<const scene::Scene> scene) {
  std::unique_ptr<Renderer> renderer(new Renderer(context, std::move(scene)));
  auto scenePass = passes::ScenePass::create(context.api());
  if (!scenePass) return Error{scenePass.error()};
  renderer->passes_.push_back(std::move(scenePass.value()));
  return renderer;
}

std::pair<float, float> Renderer::clipRange(const scene::ScenePose& pose) const {
  glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (std::size_t i = 0; i < scene_->objects.size(); ++i) {
    const auto& [meshLow, meshHigh] = meshBounds_[scene_->objects[i].mesh];
    if (meshLow.x > meshHigh.x) continue;  // empty mesh
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local((corner & 1) ? meshHigh.x : meshLow.x, (corner & 2) ? meshHigh.y : meshLow.y,
                            (corner & 4) ? meshHigh.z : meshLow.z);
      const glm::vec3 world(pose.objectToWorld[i] * glm::vec4(local, 1.0f));
      low = glm::min(low, world);
      high = glm::max(high, world);
    }
  }
  if (low.x > high.x) return {0.1f, 100.0f};  // nothing to draw
  const glm::vec3 center = 0.5f * (low + high);
  const float radius = 0.5f * glm::length(high - low);
  const float distance = glm::length(center - pose.camera.eye);
  const float farDistance = (distance + radius) * 1.01f;
  const float nearDistance = std::max(distance - radius, farDistance * kNearFarRatio);
  return {nearDistance, farDistance};
}

Result<RenderedFrame> Renderer::render(const scene::ScenePose& pose, int width, int height) {
  if (auto problem = math::cameraProblem(pose.camera)) return Error{"cannot render: " + *problem};
  const Clock::time_point start = Clock::now();
  const gl::GlApi& gl = context_.api();
  auto target = gl::RenderTarget::create(gl, width, height);
  if (!target) return Error{target.error()};

  const auto [nearDistance, farDistance] = clipRange(pose);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::mat4 worldToClip =
      math::projectionMatrix(pose.camera, aspect, nearDistance, farDistance) * math::viewMatrix(pose.camera);
  const passes::FrameContext frame{gl, *scene_, pose, meshes_, worldToClip, target.value()};

  // Timestamps bracket each stage: stage i runs between stamps i and i + 1.
  std::vector<gl::GlQuery> stamps;
  for (std::size_t i = 0; i < passes_.size() + 2; ++i) stamps.emplace_back(gl);
  gl.QueryCounter(stamps[0].id(), GL_TIMESTAMP);
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    passes_[i]->execute(frame);
    gl.QueryCounter(stamps[i + 1].id(), GL_TIMESTAMP);
  }
  RenderedFrame result{width, height, target->readRgba(), {}};
  gl.QueryCounter(stamps.back().id(), GL_TIMESTAMP);

  std::vector<GLuint64> times(stamps.size(), 0);
  for (std::size_t i = 0; i < stamps.size(); ++i) gl.GetQueryObjectui64v(stamps[i].id(), GL_QUERY_RESULT, &times[i]);
  for (std::size_t i = 0; i + 1 < stamps.size(); ++i) {
    const std::string name = i < passes_.size() ? std::string(passes_[i]->name()) : "readback";
    result.timings.stages.push_back({name, static_cast<double>(times[i + 1] - times[i]) * 1e-6});
  }
  if (const GLenum error = gl.GetError(); error != GL_NO_ERROR)
    return Error{"GL error 0x" + std::to_string(error) + " while rendering (driver: " + context_.info().renderer + ")"};
  result.timings.totalMilliseconds = millisecondsSince(start);
  return result;
}

}  // namespace specula::render
