#include "passes/MirrorGBufferPass.h"

#include <cmath>

#include "math/Transform.h"
#include "passes/PatchTessellation.h"
#include "passes/QuadricUniforms.h"

namespace specula::passes {

namespace {

constexpr int kRectPadding = 2;  // texels around the projected bounds: rasterization and the 3×3 windows
const GLenum kDrawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};

void scissorTo(const gl::GlApi& gl, const TexelRect& rect) {
  gl.Scissor(rect.low.x, rect.low.y, rect.high.x - rect.low.x, rect.high.y - rect.low.y);
}

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
  auto mesh =
      gl::ShaderProgram::build(gl, {"mirror-gbuffer/mirror-gbuffer.vert", "mirror-gbuffer/mirror-gbuffer-mesh.frag"});
  if (!mesh) return Error{mesh.error()};
  auto patch = gl::ShaderProgram::build(gl, {"common/bezier-patch.vert", "common/bezier-patch.tesc",
                                             "common/bezier-patch.tese", "mirror-gbuffer/mirror-gbuffer-patch.frag"});
  if (!patch) return Error{patch.error()};
  auto quadric =
      gl::ShaderProgram::build(gl, {"common/quadric-proxy.vert", "mirror-gbuffer/mirror-gbuffer-quadric.frag"});
  if (!quadric) return Error{quadric.error()};
  auto partLayer = gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "mirror-gbuffer/part-layer.frag"});
  if (!partLayer) return Error{partLayer.error()};
  return std::unique_ptr<MirrorGBufferPass>(new MirrorGBufferPass(
      gl, std::move(mesh.value()), std::move(patch.value()), std::move(quadric.value()), std::move(partLayer.value())));
}

int MirrorGBufferPass::attachLayer(const FrameContext& frame, int layer, bool parametric) const {
  const gl::GlApi& gl = frame.gl;
  const ReflectionResources& resources = frame.reflections;
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, resources.positionTexture(), 0, layer);
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, resources.normalTexture(), 0, layer);
  // A parametric mirror also records each texel's (u, v, patch) for the search's exact refinement.
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, parametric ? resources.surfaceTexture() : 0, 0,
                             layer);
  const int buffers = parametric ? 3 : 2;
  gl.DrawBuffers(buffers, kDrawBuffers);
  return buffers;
}

int MirrorGBufferPass::attachScratch(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  const ReflectionResources& resources = frame.reflections;
  if (!scratch_ || scratch_->size != resources.size() || scratch_->format != resources.textureFormat()) {
    scratch_.emplace(gl);  // immutable storage: new textures for a new size or format
    scratch_->size = resources.size();
    scratch_->format = resources.textureFormat();
    for (auto [texture, format] :
         {std::pair{&scratch_->position, scratch_->format}, std::pair{&scratch_->normal, scratch_->format},
          std::pair{&scratch_->surface, static_cast<GLenum>(GL_RGBA32F)}}) {
      gl.BindTexture(GL_TEXTURE_2D, texture->id());
      gl.TexStorage2D(GL_TEXTURE_2D, 1, format, scratch_->size.x, scratch_->size.y);
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);
  }
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scratch_->position.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, scratch_->normal.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, scratch_->surface.id(), 0);
  gl.DrawBuffers(3, kDrawBuffers);
  return 3;
}

void MirrorGBufferPass::drawMirror(const FrameContext& frame, const PlannedMirror& planned,
                                   const TexelRect& rect) const {
  const gl::GlApi& gl = frame.gl;
  const MirrorSlots& mirror = *planned.slots;
  const glm::ivec2 size = frame.reflections.size();
  const glm::mat4 worldToClip = frame.gbufferWorldToClip();
  scissorTo(gl, rect);
  const glm::mat4& objectToWorld = frame.pose.objectToWorld[mirror.mirrorObject];
  const scene::MirrorInfo& info = *frame.scene.objects[mirror.mirrorObject].mirror;
  if (info.exactQuadric()) {
    quadric_.use();
    setMirrorQuadric(quadric_, info, objectToWorld);
    gl.BindVertexArray(emptyVertexArray_.id());
    gl.DrawArrays(GL_TRIANGLES, 0, kQuadricProxyVertices);
    return;
  }
  const std::size_t searchMesh = frame.searchMesh(mirror.mirrorObject);
  const scene::Mesh& drawn = frame.scene.meshes[searchMesh];
  const gl::ShaderProgram& program = drawn.patches.empty() ? mesh_ : patch_;
  program.use();
  program.set("objectToWorld", objectToWorld);
  program.set("normalToWorld", math::normalMatrix(objectToWorld));
  if (mirror.partCount > 1)
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, frame.reflections.triangleParts(mirror.mirrorObject));
  if (drawn.patches.empty()) {
    // A mirror of several parts is drawn whole for depth, marking only this part's texels.
    program.set("part", mirror.partCount > 1 ? mirror.part : -1);
    frame.meshes.draw(searchMesh);
    return;
  }
  program.set("severalParts", mirror.partCount > 1 ? 1 : 0);
  setPatchView(program, objectToWorld, worldToClip, size);
  program.set("worldToObject", glm::inverse(objectToWorld));
  program.set("patchSegments", drawn.patchSegments);
  frame.meshes.drawPatches(searchMesh);
}

void MirrorGBufferPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  const glm::ivec2 size = resources.size();
  const glm::mat4 worldToClip = frame.gbufferWorldToClip();

  gl.BindFramebuffer(GL_FRAMEBUFFER, resources.framebuffer());
  gl.Viewport(0, 0, size.x, size.y);
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // positions and normals are data, not colours
  gl.Disable(GL_STENCIL_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_SCISSOR_TEST);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, resources.depthTexture(), 0);
  mesh_.use();
  mesh_.set("worldToClip", worldToClip);
  patch_.use();
  patch_.set("eyePosition", frame.pose.camera.eye);
  quadric_.use();
  quadric_.set("worldToClip", worldToClip);
  quadric_.set("eyePosition", frame.pose.camera.eye);
  partLayer_.use();
  partLayer_.set("drawnPosition", 0);
  partLayer_.set("drawnNormal", 1);
  partLayer_.set("drawnSurface", 2);

  const auto clear = [&](const TexelRect& rect, int buffers) {
    const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    const GLfloat farDepth = 1.0f;
    scissorTo(gl, rect);
    for (GLint buffer = 0; buffer < buffers; ++buffer) gl.ClearBufferfv(GL_COLOR, buffer, zero);
    gl.ClearBufferfv(GL_DEPTH, 0, &farDepth);
  };
  // A layer's cover this frame, and what it must clear: last frame's cover too, so no stale texel
  // survives outside today's.
  const auto cover = [&](int layer, const TexelRect& rect) -> const TexelRect& {
    resources.changedRect(layer) = rect.united(resources.coveredRect(layer));
    resources.coveredRect(layer) = rect;
    return resources.changedRect(layer);
  };
  std::vector<bool> done(frame.plan.mirrors.size(), false);
  for (std::size_t index = 0; index < frame.plan.mirrors.size(); ++index) {
    if (done[index]) continue;
    const PlannedMirror& planned = frame.plan.mirrors[index];
    const MirrorSlots* mirror = planned.slots;
    const bool parametric = !frame.scene.meshes[frame.searchMesh(mirror->mirrorObject)].patches.empty();
    const TexelRect rect = projectedRect(frame.worldBounds[mirror->mirrorObject], worldToClip, size);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.DepthMask(GL_TRUE);
    if (!parametric || mirror->partCount == 1) {
      const TexelRect changed = cover(mirror->layer, rect);
      clear(changed, attachLayer(frame, mirror->layer, parametric));
      if (!rect.empty()) drawMirror(frame, planned, rect);
      continue;
    }
    // A parametric mirror of several parts (the tessellation is what a drawing costs): every visible
    // part, this one first, copied from one drawing.
    std::vector<std::size_t> parts;
    TexelRect changedByAny = rect;
    for (std::size_t other = index; other < frame.plan.mirrors.size(); ++other) {
      const MirrorSlots& part = *frame.plan.mirrors[other].slots;
      if (part.mirrorObject != mirror->mirrorObject) continue;
      parts.push_back(other);
      done[other] = true;
      changedByAny = changedByAny.united(cover(part.layer, rect));
    }
    clear(changedByAny, attachScratch(frame));
    if (!rect.empty()) drawMirror(frame, planned, rect);
    // Each part's layer copied from the scratch textures, which are no longer attached.
    gl.Disable(GL_DEPTH_TEST);
    partLayer_.use();
    const GLuint drawn[] = {scratch_->position.id(), scratch_->normal.id(), scratch_->surface.id()};
    for (GLenum unit = 0; unit < 3; ++unit) {
      gl.ActiveTexture(GL_TEXTURE0 + unit);
      gl.BindTexture(GL_TEXTURE_2D, drawn[unit]);
    }
    gl.BindVertexArray(emptyVertexArray_.id());
    for (const std::size_t partIndex : parts) {
      const MirrorSlots& part = *frame.plan.mirrors[partIndex].slots;
      attachLayer(frame, part.layer, true);
      scissorTo(gl, resources.changedRect(part.layer));
      partLayer_.set("part", part.part);
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
    }
    for (GLenum unit = 0; unit < 3; ++unit) {
      gl.ActiveTexture(GL_TEXTURE0 + unit);
      gl.BindTexture(GL_TEXTURE_2D, 0);
    }
    gl.ActiveTexture(GL_TEXTURE0);
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.Enable(GL_DEPTH_TEST);
  gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, 0, 0, 0);
  const GLenum single[] = {GL_COLOR_ATTACHMENT0};
  gl.DrawBuffers(1, single);
}

}  // namespace specula::passes
