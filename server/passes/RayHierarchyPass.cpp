#include "passes/RayHierarchyPass.h"

namespace specula::passes {

namespace {
constexpr int kGroupSide = 8;  // local_size of the ray-hierarchy kernels

void dispatchOver(const gl::GlApi& gl, glm::ivec2 extent) {
  gl.DispatchCompute(static_cast<GLuint>((extent.x + kGroupSide - 1) / kGroupSide),
                     static_cast<GLuint>((extent.y + kGroupSide - 1) / kGroupSide), 1);
}
}  // namespace

Result<std::unique_ptr<RayHierarchyPass>> RayHierarchyPass::create(const gl::GlApi& gl) {
  auto leaves = gl::ShaderProgram::build(gl, {"ray-hierarchy/ray-hierarchy-leaves.comp"});
  if (!leaves) return Error{leaves.error()};
  auto level = gl::ShaderProgram::build(gl, {"ray-hierarchy/ray-hierarchy-level.comp"});
  if (!level) return Error{level.error()};
  return std::unique_ptr<RayHierarchyPass>(new RayHierarchyPass(std::move(leaves.value()), std::move(level.value())));
}

void RayHierarchyPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  resources.prepareRayHierarchy();
  const GLuint spheres = resources.rayHierarchySpheres(), cones = resources.rayHierarchyCones();
  gl.MemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  bindGBufferTextures(gl, resources);
  leaves_.use();
  setGBufferSamplers(leaves_);
  leaves_.set("eyePosition", frame.pose.camera.eye);
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    if (planned.method != PartMethod::VirtualObjects) continue;
    const int layer = planned.slots->layer;
    const TexelRect rebuild = resources.takeRayHierarchyRebuild(layer);
    if (rebuild.empty()) continue;
    leaves_.use();
    leaves_.set("layer", layer);
    leaves_.set("origin", rebuild.low);
    leaves_.set("extent", rebuild.high - rebuild.low);
    gl.BindImageTexture(0, spheres, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl.BindImageTexture(1, cones, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchOver(gl, rebuild.high - rebuild.low);
    level_.use();
    level_.set("layer", layer);
    for (int level = 1; level <= resources.rayHierarchyTopLevel(); ++level) {
      gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      const glm::ivec2 coarserSize = resources.levelSize(level);
      // Every coarser texel with a child in the rebuilt rectangle (a last texel also has the odd child).
      const glm::ivec2 low = glm::min(rebuild.low >> level, coarserSize - 1);
      const glm::ivec2 high = glm::min(((rebuild.high - 1) >> level) + 1, coarserSize);
      gl.BindImageTexture(0, spheres, level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
      gl.BindImageTexture(1, cones, level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
      gl.BindImageTexture(2, spheres, level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      gl.BindImageTexture(3, cones, level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
      level_.set("origin", low);
      level_.set("extent", high - low);
      level_.set("finerSize", resources.levelSize(level - 1));
      level_.set("coarserSize", coarserSize);
      dispatchOver(gl, high - low);
    }
  }
  gl.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace specula::passes
