#include "passes/ScenePass.h"

#include <vector>

#include "math/Transform.h"
#include "passes/PatchTessellation.h"
#include "passes/QuadricUniforms.h"
#include "passes/ShadingUniforms.h"

namespace specula::passes {

Result<std::unique_ptr<ScenePass>> ScenePass::create(const gl::GlApi& gl) {
  auto program = gl::ShaderProgram::build(gl, {"scene/scene.vert", "scene/scene.frag"});
  if (!program) return Error{program.error()};
  auto quadric = gl::ShaderProgram::build(gl, {"common/quadric-proxy.vert", "scene/scene-quadric.frag"});
  if (!quadric) return Error{quadric.error()};
  auto patches = gl::ShaderProgram::build(
      gl, {"common/bezier-patch.vert", "common/bezier-patch.tesc", "common/bezier-patch.tese", "scene/scene.frag"});
  if (!patches) return Error{patches.error()};
  auto environment =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "scene/environment-background.frag"});
  if (!environment) return Error{environment.error()};
  return std::unique_ptr<ScenePass>(new ScenePass(gl, std::move(program.value()), std::move(quadric.value()),
                                                  std::move(patches.value()), std::move(environment.value())));
}

void ScenePass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  frame.target.bind();
  gl.Enable(GL_FRAMEBUFFER_SRGB);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);  // open meshes (floors, leaves) are seen from both sides
  gl.Disable(GL_BLEND);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.ClearColor(frame.scene.background.x, frame.scene.background.y, frame.scene.background.z, 1.0f);
  gl.ClearDepth(1.0);
  gl.ClearStencil(0);
  gl.StencilMask(0xFF);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // Each mirror whose reflection is drawn this frame marks its visible pixels with its stencil value;
  // everything else writes 0, so objects in front of a mirror cut its stencil.
  std::vector<int> stencil(frame.scene.objects.size(), 0);
  for (const PlannedMirror& mirror : frame.plan.mirrors) stencil[mirror.slots->mirrorObject] = mirror.slots->stencil;
  gl.Enable(GL_STENCIL_TEST);
  gl.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);

  for (const gl::ShaderProgram* program : {&program_, &quadric_, &patches_}) {
    program->use();
    program->set("worldToClip", frame.view.worldToClip());
    program->set("eyePosition", frame.pose.camera.eye);
    setSceneLighting(*program, frame.scene);
  }
  for (std::size_t i = 0; i < frame.scene.objects.size(); ++i) {
    // Frustum culling: an object wholly outside the view costs its vertices and nothing else.
    if (!boundsInFrustum(frame.worldBounds[i], frame.pose.camera, frame.view.aspect, 0.0f)) continue;
    const scene::SceneObject& object = frame.scene.objects[i];
    const bool quadric = object.mirror && object.mirror->exactQuadric();
    const bool patches = !frame.scene.meshes[object.mesh].patches.empty();
    const gl::ShaderProgram& program = quadric ? quadric_ : patches ? patches_ : program_;
    program.use();
    if (!quadric) {  // the quadric's proxy is placed by setMirrorQuadric
      program.set("objectToWorld", frame.pose.objectToWorld[i]);
      program.set("normalToWorld", math::normalMatrix(frame.pose.objectToWorld[i]));
    }
    if (patches)
      setPatchView(program, frame.pose.objectToWorld[i], frame.view.worldToClip(),
                   {frame.target.width(), frame.target.height()});
    const scene::Material& material = frame.scene.materials[object.material];
    setMaterial(program, material, frame.textures);
    program.set("surfaceWeight", stencil[i] != 0 ? 1.0f - material.reflectivity : 1.0f);
    gl.StencilFunc(GL_ALWAYS, stencil[i], 0xFF);
    if (quadric) {
      setMirrorQuadric(program, *object.mirror, frame.pose.objectToWorld[i]);
      gl.BindVertexArray(emptyVertexArray_.id());
      gl.DrawArrays(GL_TRIANGLES, 0, kQuadricProxyVertices);
    } else if (patches) {
      frame.meshes.drawPatches(object.mesh);
    } else {
      frame.meshes.draw(object.mesh);
    }
  }
  // The environment where nothing was drawn: the far plane the triangle lies on passes only there.
  if (frame.scene.environment.kind != scene::EnvironmentKind::Colour) {
    environment_.use();
    setEnvironment(environment_, frame.scene, frame.textures);
    environment_.set("clipToWorld", glm::inverse(frame.view.worldToClip()));
    environment_.set("frameSize", glm::vec2(frame.target.width(), frame.target.height()));
    gl.StencilFunc(GL_ALWAYS, 0, 0xFF);
    gl.DepthFunc(GL_LEQUAL);
    gl.DepthMask(GL_FALSE);
    gl.BindVertexArray(emptyVertexArray_.id());
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
  }
  gl.Disable(GL_STENCIL_TEST);
}

}  // namespace specula::passes
