#include "passes/ExplosionMapPass.h"

#include <algorithm>

#include "math/Transform.h"

namespace specula::passes {

namespace {
constexpr float kSphereSlack = 1.001f;  // each sphere just past what it must bound
}  // namespace

void setExplosionMapFrame(const gl::ShaderProgram& program, const FrameContext& frame, const MirrorSlots& mirror) {
  const math::Bounds& part = frame.worldBounds[mirror.mirrorObject];
  const glm::vec3 centre = part.center();
  math::Bounds scene;
  for (const math::Bounds& bounds : frame.worldBounds) scene.add(bounds);
  float farRadius = 0.0f;
  for (int corner = 0; corner < 8; ++corner)
    farRadius = std::max(farRadius, glm::length(glm::vec3((corner & 1) ? scene.high.x : scene.low.x,
                                                          (corner & 2) ? scene.high.y : scene.low.y,
                                                          (corner & 4) ? scene.high.z : scene.low.z) -
                                                centre));
  const float nearRadius = part.radius() * kSphereSlack;
  farRadius = std::max(farRadius * kSphereSlack, nearRadius * 2.0f);
  // z towards the eye; x and y any right-handed pair square to it.
  glm::vec3 z = frame.pose.camera.eye - centre;
  z = glm::length(z) > 0.0f ? glm::normalize(z) : glm::vec3(0.0f, 0.0f, 1.0f);
  const glm::vec3 helper = std::abs(z.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 x = glm::normalize(glm::cross(helper, z));
  const glm::vec3 y = glm::cross(z, x);
  program.set("explosionCentre", centre);
  program.set("explosionAxes", glm::mat3(x, y, z));
  program.set("explosionRadii", glm::vec2(nearRadius, farRadius));
}

Result<std::unique_ptr<ExplosionMapPass>> ExplosionMapPass::create(const gl::GlApi& gl) {
  auto program = gl::ShaderProgram::build(
      gl, {"explosion-map/explosion-map.vert", "explosion-map/explosion-map.geom", "explosion-map/explosion-map.frag"});
  if (!program) return Error{program.error()};
  return std::unique_ptr<ExplosionMapPass>(new ExplosionMapPass(gl, std::move(program.value())));
}

void ExplosionMapPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  ReflectionResources& resources = frame.reflections;
  const int side = frame.settings.explosionMapSize;
  resources.prepareExplosionMaps(side);
  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.Viewport(0, 0, side, side);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  gl.DrawBuffers(2, drawBuffers);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.DepthMask(GL_TRUE);
  program_.use();
  program_.set("eyePosition", frame.pose.camera.eye);
  const GLfloat empty[] = {0.0f, 0.0f, 0.0f, 0.0f};
  const GLfloat farDepth = 1.0f;
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    if (planned.method != PartMethod::VirtualObjects) continue;
    const MirrorSlots& mirror = *planned.slots;
    const glm::mat4& objectToWorld = frame.pose.objectToWorld[mirror.mirrorObject];
    setExplosionMapFrame(program_, frame, mirror);
    program_.set("objectToWorld", objectToWorld);
    program_.set("normalToWorld", math::normalMatrix(objectToWorld));
    program_.set("part", mirror.partCount > 1 ? mirror.part : -1);
    if (mirror.partCount > 1)
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, resources.triangleParts(mirror.mirrorObject));
    for (int map = 0; map < 2; ++map) {  // near, then far
      const int layer = 2 * mirror.layer + map;
      gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, resources.explosionPositions(), 0, layer);
      gl.FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, resources.explosionNormals(), 0, layer);
      gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, resources.explosionDepth(), 0);
      gl.ClearBufferfv(GL_COLOR, 0, empty);
      gl.ClearBufferfv(GL_COLOR, 1, empty);
      gl.ClearBufferfv(GL_DEPTH, 0, &farDepth);
      program_.set("farMap", map);
      frame.meshes.draw(frame.searchMesh(mirror.mirrorObject));
    }
  }
  const GLenum single[] = {GL_COLOR_ATTACHMENT0};
  gl.DrawBuffers(1, single);
}

}  // namespace specula::passes
