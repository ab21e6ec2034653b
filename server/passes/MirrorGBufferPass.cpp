#include "passes/MirrorGBufferPass.h"

#include <cmath>

#include "math/Transform.h"
#include "passes/PatchTessellation.h"
#include "passes/QuadricUniforms.h"

namespace specula::passes {

namespace {

constexpr int kRectPadding = 2;  // texels around the projected bounds: rasterization and the 3×3 windows

// The G-buffer texels a world box can cover; everything when the box reaches behind the eye.
TexelRect projectedRect(const math::Bounds& bounds, const glm::mat4& worldToClip, glm::ivec2 size) {
  const TexelRect everything{{0, 0}, size};
  glm::vec2 low(1e30f), high(-1e30f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 clip = worldToClip * glm::vec4((corner & 1) ? bounds.high.x : bounds.low.x,
                                                   (corner & 2) ? bounds.high.y : bounds.low.y,
                                                   (corner & 4) ? bounds.high.z : bounds.low.z, 1.0f);
    if (clip.w <= 1e-6f) return everything;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    low = glm::min(low, ndc);
    high = glm::max(high, ndc);
  }
  const glm::vec2 texelLow = (low * 0.5f + 0.5f) * glm::vec2(size);
  const glm::vec2 texelHigh = (high * 0.5f + 0.5f) * glm::vec2(size);
  TexelRect rect{glm::ivec2(glm::floor(texelLow)) - kRectPadding, glm::ivec2(glm::ceil(texelHigh)) + kRectPadding};
  rect.low = glm::clamp(rect.low, glm::ivec2(0), size);
  rect.high = glm::clamp(rect.high, glm::ivec2(0), size);
  return rect;
}

}  // namespace

Result<std::unique_ptr<MirrorGBufferPass>> MirrorGBufferPass::create(const gl::GlApi& gl) {
  auto mesh = gl::ShaderProgram::build(gl, {"mirror-gbuffer/mirror-gbuffer.vert", "mirror-gbuffer/mirror-gbuffer-mesh.frag"});
  if (!mesh) return Error{mesh.error()};
  auto patch = gl::ShaderProgram::build(gl, {"common/bezier-patch.vert", "common/bezier-patch.tesc", "common/bezier-patch.tese",
                                             "mirror-gbuffer/mirror-gbuffer-patch.frag"});
  if (!patch) return Error{patch.error()};
  auto quadric = gl::ShaderProgram::build(gl, {"common/quadric-proxy.vert", "mirror-gbuffer/mirror-gbuffer-quadric.frag"});
  if (!quadric) return Error{quadric.error()};
  return std::unique_ptr<MirrorGBufferPass>(new MirrorGBufferPass(gl, std::move(mesh.value()), std::move(patch.value()),
                                                             std::move(quadric.value())));
}

void MirrorGBufferPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  const glm::ivec2 size = resources.size();
  const glm::mat4 worldToClip = frame.gbufferWorldToClip();

  gl.BindFramebuffer(GL_FRAMEBUFFER, resources.framebuffer());
  gl.Viewport(0, 0, size.x, size.y);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // positions and normals are data, not colours
  gl.Disable(GL_STENCIL_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.DepthMask(GL_TRUE);
  gl.Enable(GL_SCISSOR_TEST);
  mesh_.use();
  mesh_.set("worldToClip", worldToClip);
  patch_.use();
  patch_.set("eyePosition", frame.pose.camera.eye);
  quadric_.use();
  quadric_.set("worldToClip", worldToClip);
  quadric_.set("eyePosition", frame.pose.camera.eye);

  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, resources.positionTexture(), 0, mirror->layer);
    gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, resources.normalTexture(), 0, mirror->layer);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, resources.depthTexture(), 0);
    // A parametric mirror also records each texel's (u, v, patch) for the search's exact refinement.
    const bool parametric = !frame.scene.meshes[frame.searchMesh(mirror->mirrorObject)].patches.empty();
    if (parametric) gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, resources.surfaceTexture(), 0, mirror->layer);
    gl.DrawBuffers(parametric ? 3 : 2, drawBuffers);
    const TexelRect rect = projectedRect(frame.worldBounds[mirror->mirrorObject], worldToClip, size);
    const TexelRect changed = rect.united(resources.coveredRect(mirror->layer));
    resources.coveredRect(mirror->layer) = rect;
    resources.changedRect(mirror->layer) = changed;

    // Clear what the mirror covered last frame too, so no stale texel survives outside today's cover.
    const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    const GLfloat farDepth = 1.0f;
    gl.Scissor(changed.low.x, changed.low.y, changed.high.x - changed.low.x, changed.high.y - changed.low.y);
    gl.ClearBufferfv(GL_COLOR, 0, zero);
    gl.ClearBufferfv(GL_COLOR, 1, zero);
    if (parametric) gl.ClearBufferfv(GL_COLOR, 2, zero);
    gl.ClearBufferfv(GL_DEPTH, 0, &farDepth);
    if (rect.empty()) continue;
    gl.Scissor(rect.low.x, rect.low.y, rect.high.x - rect.low.x, rect.high.y - rect.low.y);
    const glm::mat4& objectToWorld = frame.pose.objectToWorld[mirror->mirrorObject];
    const scene::MirrorInfo& info = *frame.scene.objects[mirror->mirrorObject].mirror;
    if (info.exactQuadric()) {
      quadric_.use();
      setMirrorQuadric(quadric_, info, objectToWorld);
      gl.BindVertexArray(emptyVertexArray_.id());
      gl.DrawArrays(GL_TRIANGLES, 0, kQuadricProxyVertices);
      continue;
    }
    const std::size_t searchMesh = frame.searchMesh(mirror->mirrorObject);
    const scene::Mesh& drawn = frame.scene.meshes[searchMesh];
    const gl::ShaderProgram& program = drawn.patches.empty() ? mesh_ : patch_;
    program.use();
    program.set("objectToWorld", objectToWorld);
    program.set("normalToWorld", math::normalMatrix(objectToWorld));
    if (!drawn.patches.empty()) setPatchView(program, objectToWorld, worldToClip, size);
    // A mirror of several parts draws them all for depth, and marks only this part's texels.
    program.set("part", mirror->partCount > 1 ? mirror->part : -1);
    if (mirror->partCount > 1)
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, resources.triangleParts(mirror->mirrorObject));
    if (drawn.patches.empty()) {
      frame.meshes.draw(searchMesh);
      continue;
    }
    program.set("worldToObject", glm::inverse(objectToWorld));
    program.set("patchSegments", drawn.patchSegments);
    frame.meshes.drawPatches(searchMesh);
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, 0, 0, 0);
  const GLenum single[] = {GL_COLOR_ATTACHMENT0};
  gl.DrawBuffers(1, single);
}

}  // namespace specula::passes
