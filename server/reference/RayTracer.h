#pragma once
// Exact reference images: an Embree ray tracer with the rasterizer's camera and shading, and exact
// mirror reflections (on the analytic surface where a closed mirror has one). CPU only, no GL.
#include <cstdint>
#include <memory>
#include <vector>

#include "base/Result.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"

struct RTCDeviceTy;

namespace specula::reference {

class PosedScene;
class PixelTracer;

struct RayTracerOptions {
  int width = 640;  // pixels
  int height = 480;
  // Mirror reflections followed per pixel; 1 is what single-bounce virtual-object methods aim at,
  // 0 shows mirrors as plain shaded surfaces. A mirror reached after the last allowed bounce shows
  // its own shaded colour at full weight (what a virtual object of that mirror shows when rasterized).
  int maxBounces = 1;
  // Workers sharing the image rows; 0: std::thread::hardware_concurrency(). (Embree builds its
  // acceleration structure on its own TBB threads.)
  unsigned threads = 0;
  // Rays per pixel, through math::samplePattern's points (the rasterizer's anti-aliased frames take
  // the same), their linear colours averaged: 1, 2, 4, 8 or 16.
  int samples = 1;
};

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // sRGB bytes as a GL sRGB8 framebuffer stores them, row 0 at the top
  // One per pixel, row 0 at the top: 1 where more than half the primary rays hit an object with
  // SceneObject::mirror, else 0.
  std::vector<std::uint8_t> mirrorMask;
  double milliseconds = 0.0;  // wall time of render(), building the acceleration structure included
};

// Per pixel: one primary ray through the pixel centre, or `samples` through the sample points, averaged.
// Textures are filtered over the pixel's ray cone (shading.glsl's pixelFootprint). At a hit: the colour of
// shaders/common/shading.glsl; at a mirror (SceneObject::mirror with reflectivity r > 0, bounces left)
// (1 − r) · that colour + r · the colour seen along the ray reflected about the surface normal;
// nothing hit: the scene's environment (reference/EnvironmentRadiance). Colours are linear until the final sRGB
// encoding. Reflected rays see only objects with SceneObject::reflected, as the reflection methods do.
class RayTracer {
 public:
  // `scene` must pass scene::sceneProblem(). Fails when Embree cannot create a device.
  static Result<std::unique_ptr<RayTracer>> create(std::shared_ptr<const scene::Scene> scene);
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  const scene::Scene& scene() const { return *scene_; }

  // Renders the scene at `pose` (which must come from this scene). Fails on a camera that cannot
  // produce a view, a non-positive size or bounce count, or an Embree error. Safe to call concurrently.
  Result<ReferenceImage> render(const scene::ScenePose& pose, const RayTracerOptions& options) const;
  // The same from a pose's geometry built already (posedScene), seen by `camera`.
  Result<ReferenceImage> render(std::shared_ptr<const PosedScene> posed, const math::Camera& camera,
                                const RayTracerOptions& options) const;

  // The pose's geometry (objects placed, deformed), which every camera of that pose can share.
  Result<std::shared_ptr<const PosedScene>> posedScene(const scene::ScenePose& pose) const;
  // Traces single pixels of `camera`'s view of `posed` (from this tracer's scene) as render() traces
  // them; `options.threads` is unused. Fails where render() would on the camera or the options.
  Result<std::unique_ptr<PixelTracer>> pixelTracer(std::shared_ptr<const PosedScene> posed, const math::Camera& camera,
                                                   const RayTracerOptions& options) const;

 private:
  RayTracer(std::shared_ptr<const scene::Scene> scene, RTCDeviceTy* device);

  std::shared_ptr<const scene::Scene> scene_;
  RTCDeviceTy* device_;
};

}  // namespace specula::reference
