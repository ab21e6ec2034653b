#include "passes/EnvironmentMapPass.h"

#include <algorithm>
#include <array>
#include <glm/gtc/matrix_transform.hpp>

#include "math/Transform.h"
#include "passes/ShadingUniforms.h"

namespace specula::passes {

namespace {

// GL's cube faces in order (+x, -x, +y, -y, +z, -z): the direction each looks along and its up
// vector, which bake in the cube map's left-handed face coordinates.
struct CubeFace {
  glm::vec3 forward, up;
};
constexpr std::array<CubeFace, 6> kCubeFaces{{{{1, 0, 0}, {0, -1, 0}},
                                              {{-1, 0, 0}, {0, -1, 0}},
                                              {{0, 1, 0}, {0, 0, 1}},
                                              {{0, -1, 0}, {0, 0, -1}},
                                              {{0, 0, 1}, {0, -1, 0}},
                                              {{0, 0, -1}, {0, -1, 0}}}};

// The capture point: the analytic shape's centre when the mirror has one, else its bounds' centre.
glm::vec3 mirrorCentre(const FrameContext& frame, std::size_t mirrorObject) {
  const scene::MirrorInfo& mirror = *frame.scene.objects[mirrorObject].mirror;
  if (mirror.analytic)
    return glm::vec3(frame.pose.objectToWorld[mirrorObject] * glm::vec4(mirror.analytic->center, 1.0f));
  return frame.worldBounds[mirrorObject].center();
}

}  // namespace

Result<std::unique_ptr<EnvironmentMapPass>> EnvironmentMapPass::create(const gl::GlApi& gl) {
  auto capture = gl::ShaderProgram::build(gl, {"scene/scene.vert", "scene/scene.frag"});
  if (!capture) return Error{capture.error()};
  auto lookup =
      gl::ShaderProgram::build(gl, {"common/fullscreen-triangle.vert", "environment-map/environment-map.frag"});
  if (!lookup) return Error{lookup.error()};
  return std::unique_ptr<EnvironmentMapPass>(
      new EnvironmentMapPass(gl, std::move(capture.value()), std::move(lookup.value())));
}

void EnvironmentMapPass::prepare(const gl::GlApi& gl, int faceSize) {
  if (faceSize == faceSize_) return;
  faceSize_ = faceSize;
  cube_ = gl::GlTexture(gl);  // immutable storage: replace it
  depth_ = gl::GlTexture(gl);
  gl.BindTexture(GL_TEXTURE_CUBE_MAP, cube_.id());
  gl.TexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA16F, faceSize, faceSize);
  gl.TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.BindTexture(GL_TEXTURE_CUBE_MAP, 0);
  gl.BindTexture(GL_TEXTURE_2D, depth_.id());
  gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, faceSize, faceSize);
  gl.BindTexture(GL_TEXTURE_2D, 0);
}

void EnvironmentMapPass::capture(const FrameContext& frame, std::size_t mirrorObject, const glm::vec3& centre) const {
  const gl::GlApi& gl = frame.gl;
  // Near enough for objects touching the mirror, far enough for everything in the scene.
  math::Bounds all;
  for (const math::Bounds& bounds : frame.worldBounds) all.add(bounds);
  const float farDistance = (glm::length(all.center() - centre) + all.radius()) * 1.01f + 1e-3f;
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, farDistance * 1e-5f, farDistance);

  gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  gl.Viewport(0, 0, faceSize_, faceSize_);
  gl.Disable(GL_STENCIL_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_FRAMEBUFFER_SRGB);  // the cube holds linear colour
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);  // alpha 0 where nothing is captured: the lookup adds the environment there
  capture_.use();
  capture_.set("eyePosition", centre);
  capture_.set("surfaceWeight", 1.0f);  // one bounce: a mirror seen in a mirror shows its own colour
  setSceneLighting(capture_, frame.scene);
  for (std::size_t face = 0; face < kCubeFaces.size(); ++face) {
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                            static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), cube_.id(), 0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    capture_.set("worldToClip",
                 projection * glm::lookAt(centre, centre + kCubeFaces[face].forward, kCubeFaces[face].up));
    // What any of the mirror's parts reflects (each part leaves out what it cannot show).
    for (const PlannedMirror& part : frame.plan.mirrors) {
      if (part.slots->mirrorObject != mirrorObject) continue;
      for (const ReflectionSlotRange* range : part.reflected) {
        const bool drawnForAnEarlierPart =
            std::any_of(frame.plan.mirrors.data(), &part, [&](const PlannedMirror& earlier) {
              return earlier.slots->mirrorObject == mirrorObject &&
                     std::any_of(earlier.reflected.begin(), earlier.reflected.end(),
                                 [&](const ReflectionSlotRange* drawn) { return drawn->object == range->object; });
            });
        if (drawnForAnEarlierPart) continue;
        const scene::SceneObject& object = frame.scene.objects[range->object];
        capture_.set("objectToWorld", frame.pose.objectToWorld[range->object]);
        capture_.set("normalToWorld", math::normalMatrix(frame.pose.objectToWorld[range->object]));
        setMaterial(capture_, frame.scene.materials[object.material], frame.textures);
        frame.meshes.draw(object.mesh);
      }
    }
  }
}

void EnvironmentMapPass::execute(const FrameContext& frame) {
  const gl::GlApi& gl = frame.gl;
  const ReflectionResources& resources = frame.reflections;
  prepare(gl, frame.settings.environmentMapSize);
  gl.Disable(GL_CULL_FACE);                 // open meshes are seen from both sides
  gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // no seams where a lookup straddles two faces
  // The environment-map method serves every mirror; otherwise the planner picked it for some.
  const bool everyMirror = frame.settings.method == ReflectionMethod::EnvironmentMap;
  for (const PlannedMirror& planned : frame.plan.mirrors) {
    const MirrorSlots* mirror = planned.slots;
    if (!everyMirror && planned.method != PartMethod::EnvironmentMap) continue;
    // One cube per mirror, looked up from each of its parts' layers.
    if (mirror->part == 0) capture(frame, mirror->mirrorObject, mirrorCentre(frame, mirror->mirrorObject));

    frame.target.bind();
    gl.Enable(GL_FRAMEBUFFER_SRGB);
    gl.Enable(GL_STENCIL_TEST);
    gl.StencilMask(0);
    gl.StencilFunc(GL_EQUAL, mirror->stencil, 0xFF);
    gl.Disable(GL_DEPTH_TEST);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_ONE, GL_ONE);
    lookup_.use();
    setEnvironment(lookup_, frame.scene, frame.textures);
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_CUBE_MAP, cube_.id());
    bindGBufferTextures(gl, resources);
    setGBufferSamplers(lookup_);
    lookup_.set("environment", 2);
    lookup_.set("layer", mirror->layer);
    setGBufferPixelMapping(lookup_, resources);
    lookup_.set("eyePosition", frame.pose.camera.eye);
    lookup_.set("reflectivity", frame.scene.materials[frame.scene.objects[mirror->mirrorObject].material].reflectivity);
    lookup_.set("environmentReach", everyMirror ? 0.0f : planned.environmentReach);
    lookup_.set("errorBudget", frame.settings.errorBudgetPixels);
    gl.BindVertexArray(emptyVertexArray_.id());
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }
  gl.Disable(GL_BLEND);
  gl.Disable(GL_STENCIL_TEST);
  gl.StencilMask(0xFF);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
}

}  // namespace specula::passes
