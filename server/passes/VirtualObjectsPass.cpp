#include "passes/VirtualObjectsPass.h"

#include <limits>

#include "math/Transform.h"
#include "passes/ReflectionResources.h"
#include "passes/ShadingUniforms.h"

namespace specula::passes {

namespace {
// Virtual vertices lie a whole path (eye → mirror → object) away: push the far plane out.
constexpr float kVirtualFarScale = 3.0f;
}  // namespace

Result<std::unique_ptr<VirtualObjectsPass>> VirtualObjectsPass::create(const gl::GlApi& gl) {
  auto objects = gl::ShaderProgram::build(gl, {"virtual-objects/virtual-objects.vert", "virtual-objects/virtual-objects.geom",
                                               "virtual-objects/virtual-objects.frag"});
  if (!objects) return Error{objects.error()};
  auto tessellated =
      gl::ShaderProgram::build(gl, {"virtual-objects/virtual-objects-tessellated.vert", "virtual-objects/virtual-objects.frag"});
  if (!tessellated) return Error{tessellated.error()};
  auto region = gl::ShaderProgram::build(gl, {"virtual-objects/mirror-region.vert", "virtual-objects/mirror-region.frag"});
  if (!region) return Error{region.error()};
  auto rayCast = gl::ShaderProgram::build(gl, {"virtual-objects/mirror-region.vert", "virtual-objects/ray-cast.frag"});
  if (!rayCast) return Error{rayCast.error()};
  auto composite = gl::ShaderProgram::build(gl, {"virtual-objects/mirror-region.vert", "virtual-objects/reflection-composite.frag"});
  if (!composite) return Error{composite.error()};
  return std::unique_ptr<VirtualObjectsPass>(new VirtualObjectsPass(gl, std::move(objects.value()), std::move(tessellated.value()),
                                                                    std::move(region.value()), std::move(rayCast.value()),
                                                                    std::move(composite.value())));
}

void VirtualObjectsPass::drawMesh(const FrameContext& frame, const ReflectionSlotRange& range) const {
  frame.setReflectedObject(objects_, range);
  setMaterial(objects_, frame.scene.materials[frame.scene.objects[range.object].material]);
  frame.meshes.draw(frame.scene.objects[range.object].mesh);
}

void VirtualObjectsPass::drawObjects(const FrameContext& frame, const PlannedMirror& mirror) const {
  if (!frame.plan.tessellate) {
    objects_.use();
    for (const ReflectionSlotRange* range : mirror.reflected) drawMesh(frame, *range);
    return;
  }
  const TessellationBuffers& tessellation = frame.reflections.tessellation();
  for (const TessellatedRange& range : tessellation.ranges()) {
    if (range.mirror != mirror.slots || range.triangles == 0) continue;  // another mirror, or another part of this one
    if (range.fromMesh) {
      objects_.use();
      drawMesh(frame, *range.object);
      continue;
    }
    tessellated_.use();
    frame.gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, tessellation.finished());
    frame.gl.BindVertexArray(emptyVertexArray_.id());
    setMaterial(tessellated_, frame.scene.materials[frame.scene.objects[range.object->object].material]);
    frame.gl.DrawArrays(GL_TRIANGLES, 3 * range.firstTriangle, 3 * range.triangles);
  }
}

void VirtualObjectsPass::rayCast(const FrameContext& frame, const MirrorSlots& mirror, std::size_t objectIndex) const {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  const scene::SceneObject& object = frame.scene.objects[objectIndex];
  const ReflectionResources::MeshBvh& bvh = resources.meshBvh(object.mesh);
  const glm::mat4& objectToWorld = frame.pose.objectToWorld[objectIndex];
  rayCast_.use();  // the G-buffer textures are bound by execute()
  rayCast_.set("gbufferPosition", 0);
  rayCast_.set("gbufferNormal", 1);
  setGBufferPixelMapping(rayCast_, resources);
  rayCast_.set("layer", mirror.layer);
  rayCast_.set("eyePosition", frame.pose.camera.eye);
  rayCast_.set("objectToWorld", objectToWorld);
  rayCast_.set("worldToObject", glm::inverse(objectToWorld));
  rayCast_.set("normalToWorld", math::normalMatrix(objectToWorld));
  rayCast_.set("worldToClip", frame.view.worldToClip(glm::vec2(1.0f), kVirtualFarScale));
  rayCast_.set("minDistance", bvh.minDistance);
  rayCast_.set("reflectivity", frame.scene.materials[frame.scene.objects[mirror.mirrorObject].material].reflectivity);
  setSceneLighting(rayCast_, frame.scene);
  setMaterial(rayCast_, frame.scene.materials[object.material]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, bvh.nodes.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, bvh.triangles.id());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, frame.meshes.vertexBuffer(object.mesh));
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, frame.meshes.indexBuffer(object.mesh));
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void VirtualObjectsPass::resetMirrorDepth(const FrameContext& frame) const {
  // Virtual objects lie behind the mirror's surface: its pixels start at the far plane.
  const gl::GlApi& gl = frame.gl;
  region_.use();
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.Disable(GL_BLEND);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_ALWAYS);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void VirtualObjectsPass::bindReflectionBuffer(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  const glm::ivec2 size(frame.target.width(), frame.target.height());
  if (size != reflectionSize_) {
    reflection_ = gl::GlTexture(gl);  // immutable storage: replace it
    gl.BindTexture(GL_TEXTURE_2D, reflection_.id());
    gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, size.x, size.y);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    reflectionSize_ = size;
  }
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, reflection_.id(), 0);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, frame.target.depthStencilTexture(), 0);
  gl.Viewport(0, 0, size.x, size.y);
}

void VirtualObjectsPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  bindReflectionBuffer(frame);
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // linear until the composite writes the frame
  gl.Disable(GL_BLEND);
  gl.Disable(GL_SCISSOR_TEST);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const GLfloat nothing[] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl.ClearBufferfv(GL_COLOR, 0, nothing);
  gl.Enable(GL_STENCIL_TEST);
  gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl.StencilMask(0);
  gl.Enable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);  // reflection flips winding; open meshes are two-sided anyway
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());

  gl.ActiveTexture(GL_TEXTURE1);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, frame.reflections.normalTexture());
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, frame.reflections.positionTexture());
  for (const gl::ShaderProgram* objects : {&objects_, &tessellated_}) {
    objects->use();
    objects->set("worldToClip", frame.view.worldToClip(glm::vec2(1.0f), kVirtualFarScale));
    objects->set("gbufferPosition", 0);
    objects->set("gbufferNormal", 1);
    objects->set("eyePosition", frame.pose.camera.eye);
    objects->set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
    setGBufferPixelMapping(*objects, frame.reflections);
    setSceneLighting(*objects, frame.scene);
  }

  // Every draw below touches one mirror's pixels only: scissored to its parts' screen rectangle, a
  // frame of many small mirrors does not test the whole frame's stencil once per mirror.
  gl.Enable(GL_SCISSOR_TEST);
  const auto scissorToMirror = [&](std::size_t mirrorObject) {
    glm::vec4 rect(std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
                   std::numeric_limits<float>::lowest());
    for (const PlannedMirror& part : frame.plan.mirrors) {
      if (part.slots->mirrorObject != mirrorObject) continue;
      const glm::vec4 covered = frame.reflections.coveredFramePixels(part.slots->layer);
      rect = glm::vec4(glm::min(glm::vec2(rect), glm::vec2(covered)), glm::max(glm::vec2(rect.z, rect.w), glm::vec2(covered.z, covered.w)));
    }
    const glm::ivec2 size(frame.target.width(), frame.target.height());
    const glm::ivec2 low = glm::clamp(glm::ivec2(glm::floor(glm::vec2(rect.x, rect.y))), glm::ivec2(0), size);
    const glm::ivec2 high = glm::clamp(glm::ivec2(glm::ceil(glm::vec2(rect.z, rect.w))), low, size);
    gl.Scissor(low.x, low.y, high.x - low.x, high.y - low.y);
  };

  // Per mirror: its depth reset to the far plane, then each part's self-reflection and virtual
  // objects; every fragment is an exact hit at its exact depth, so the nearest wins in one pass.
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    gl.StencilFunc(GL_EQUAL, mirror->stencil, 0xFF);
    if (mirror->part == 0) {
      scissorToMirror(mirror->mirrorObject);
      resetMirrorDepth(frame);
    }
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
    setForBoth("layer", mirror->layer);
    setForBoth("mirrorRect", frame.reflections.coveredFramePixels(mirror->layer));
    setForBoth("everyCornerReflected", mirror->kind == scene::SurfaceKind::Convex ? 0 : 1);
    setForBoth("reflectivity", frame.scene.materials[frame.scene.objects[mirror->mirrorObject].material].reflectivity);
    if (mirror->seesItself) rayCast(frame, *mirror, mirror->mirrorObject);
    if (planned.method == PartMethod::RayCast) {
      for (const ReflectionSlotRange* range : planned.reflected) rayCast(frame, *mirror, range->object);
    } else {
      drawObjects(frame, planned);
    }
  }

  // Each mirror's reflection (or its reflected background) added over its surface in the frame.
  frame.target.bind();
  gl.Enable(GL_FRAMEBUFFER_SRGB);
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_ONE, GL_ONE);
  composite_.use();
  gl.ActiveTexture(GL_TEXTURE2);
  gl.BindTexture(GL_TEXTURE_2D, reflection_.id());
  gl.ActiveTexture(GL_TEXTURE0);
  composite_.set("reflection", 2);
  gl.BindVertexArray(emptyVertexArray_.id());
  gl.Enable(GL_SCISSOR_TEST);
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    if (mirror->part != 0) continue;  // once per mirror
    const float reflectivity = frame.scene.materials[frame.scene.objects[mirror->mirrorObject].material].reflectivity;
    gl.StencilFunc(GL_EQUAL, mirror->stencil, 0xFF);
    scissorToMirror(mirror->mirrorObject);
    composite_.set("reflectedBackground", reflectivity * frame.scene.background);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_STENCIL_TEST);
  gl.StencilMask(0xFF);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_LESS);
}

}  // namespace specula::passes
