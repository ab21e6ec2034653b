#include "passes/GBufferPyramidPass.h"

namespace specula::passes {

namespace {
constexpr int kGroupSide = 8;  // local_size of gbuffer-pyramid.comp
}  // namespace

Result<std::unique_ptr<GBufferPyramidPass>> GBufferPyramidPass::create(const gl::GlApi& gl) {
  auto full = gl::ShaderProgram::build(gl, {"gbuffer-pyramid/gbuffer-pyramid.comp"});
  if (!full) return Error{full.error()};
  auto half = gl::ShaderProgram::build(gl, {"gbuffer-pyramid/gbuffer-pyramid-half.comp"});
  if (!half) return Error{half.error()};
  return std::unique_ptr<GBufferPyramidPass>(new GBufferPyramidPass(std::move(full.value()), std::move(half.value())));
}

void GBufferPyramidPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  const gl::ShaderProgram& program = resources.precision() == GBufferPrecision::Float16 ? half_ : full_;
  const GLenum format = resources.textureFormat();
  program.use();
  gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    const TexelRect changed = resources.changedRect(mirror->layer);
    if (changed.empty()) continue;
    program.set("layer", mirror->layer);
    for (int level = 1; level <= resources.coarseLevel(); ++level) {
      gl.BindImageTexture(0, resources.positionTexture(), level - 1, GL_TRUE, 0, GL_READ_ONLY, format);
      gl.BindImageTexture(1, resources.normalTexture(), level - 1, GL_TRUE, 0, GL_READ_ONLY, format);
      gl.BindImageTexture(2, resources.positionTexture(), level, GL_TRUE, 0, GL_WRITE_ONLY, format);
      gl.BindImageTexture(3, resources.normalTexture(), level, GL_TRUE, 0, GL_WRITE_ONLY, format);
      const glm::ivec2 coarserSize = resources.levelSize(level);
      const glm::ivec2 low = glm::clamp(changed.low >> level, glm::ivec2(0), coarserSize);
      const glm::ivec2 high = glm::clamp(((changed.high - 1) >> level) + 1, glm::ivec2(0), coarserSize);
      const glm::ivec2 extent = high - low;
      if (extent.x <= 0 || extent.y <= 0) break;
      program.set("origin", low);
      program.set("finerSize", resources.levelSize(level - 1));
      program.set("coarserSize", coarserSize);
      gl.DispatchCompute(static_cast<GLuint>((extent.x + kGroupSide - 1) / kGroupSide),
                         static_cast<GLuint>((extent.y + kGroupSide - 1) / kGroupSide), 1);
      gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
  }
  gl.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace specula::passes
