#include "passes/VirtualObjectsPass.h"

#include <array>

#include "passes/ShadingUniforms.h"

namespace specula::passes {

namespace {
constexpr std::array<std::string_view, 3> kReads{"reflected-vertices", "tessellated-triangles", "color"};  // one of the first two
constexpr std::array<std::string_view, 1> kWrites{"color"};
// Virtual vertices lie a whole path (eye → mirror → object) away: push the far plane out.
constexpr float kVirtualFarScale = 3.0f;
}  // namespace

Result<std::unique_ptr<VirtualObjectsPass>> VirtualObjectsPass::create(const gl::GlApi& gl) {
  auto objects = gl::ShaderProgram::build(gl, {"virtual-objects/virtual-objects.vert", "virtual-objects/virtual-objects.geom",
                                               "virtual-objects/virtual-objects.frag"});
  if (!objects) return Error{objects.error()};
  auto tessellated = gl::ShaderProgram::build(gl, {"virtual-objects/virtual-objects-tessellated.vert", "virtual-objects/virtual-objects.geom",
                                                   "virtual-objects/virtual-objects.frag"});
  if (!tessellated) return Error{tessellated.error()};
  auto region = gl::ShaderProgram::build(gl, {"virtual-objects/mirror-region.vert", "virtual-objects/mirror-region.frag"});
  if (!region) return Error{region.error()};
  return std::unique_ptr<VirtualObjectsPass>(
      new VirtualObjectsPass(gl, std::move(objects.value()), std::move(tessellated.value()), std::move(region.value())));
}

std::span<const std::string_view> VirtualObjectsPass::reads() const { return kReads; }
std::span<const std::string_view> VirtualObjectsPass::writes() const { return kWrites; }

void VirtualObjectsPass::drawMesh(const FrameContext& frame, const ReflectionSlotRange& range) const {
  frame.setReflectedObject(objects_, range);
  setMaterial(objects_, frame.scene.materials[frame.scene.objects[range.object].material]);
  frame.meshes.draw(frame.scene.objects[range.object].mesh);
}

void VirtualObjectsPass::drawObjects(const FrameContext& frame, const MirrorSlots& mirror) const {
  if (!frame.plan.tessellate) {
    objects_.use();
    for (const ReflectionSlotRange& range : mirror.reflected) drawMesh(frame, range);
    return;
  }
  const TessellationBuffers& tessellation = frame.reflections.tessellation();
  for (const TessellatedRange& range : tessellation.ranges()) {
    if (range.mirrorObject != mirror.mirrorObject || range.triangles == 0) continue;
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

void VirtualObjectsPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  frame.target.bind();
  gl.Enable(GL_FRAMEBUFFER_SRGB);
  gl.Enable(GL_STENCIL_TEST);
  gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl.StencilMask(0);
  gl.Enable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);  // reflection flips winding; open meshes are two-sided anyway
  gl.BlendFunc(GL_ONE, GL_ONE);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, frame.reflections.reflectedVertices());

  for (const gl::ShaderProgram* objects : {&objects_, &tessellated_}) {
    objects->use();
    objects->set("worldToClip", frame.view.worldToClip(glm::vec2(1.0f), kVirtualFarScale));
    setSceneLighting(*objects, frame.scene);
  }

  for (const MirrorSlots* mirror : frame.plan.mirrors) {
    const float reflectivity = frame.scene.materials[frame.scene.objects[mirror->mirrorObject].material].reflectivity;
    gl.StencilFunc(GL_EQUAL, mirror->layer + 1, 0xFF);

    // 1. Reset depth inside this mirror to the far plane: virtual objects lie behind its surface.
    region_.use();
    gl.BindVertexArray(emptyVertexArray_.id());
    gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.Disable(GL_BLEND);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_ALWAYS);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);

    // 2. Depth of the nearest virtual surface, 3. shade only that surface, added over the mirror.
    setForBoth("reflectivity", reflectivity);
    gl.DepthFunc(GL_LESS);
    setForBoth("depthOnly", 1);
    drawObjects(frame, *mirror);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Enable(GL_BLEND);
    gl.DepthMask(GL_FALSE);
    gl.DepthFunc(GL_EQUAL);
    setForBoth("depthOnly", 0);
    drawObjects(frame, *mirror);

    // 4. Where no virtual object landed, the mirror reflects the background.
    region_.use();
    region_.set("reflectedBackground", reflectivity * frame.scene.background);
    gl.BindVertexArray(emptyVertexArray_.id());
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }
  gl.Disable(GL_BLEND);
  gl.Disable(GL_STENCIL_TEST);
  gl.StencilMask(0xFF);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_LESS);
}

}  // namespace specula::passes
