#pragma once
// One camera's view of one posed scene, traced a pixel at a time: what RayTracer::render() computes
// for every pixel, and what the live accuracy estimate computes for a sample of them.
#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include "math/Camera.h"
#include "reference/PosedScene.h"
#include "reference/PrimaryRays.h"
#include "reference/SurfaceShader.h"

namespace specula::reference {

struct TracedPixel {
  std::array<std::uint8_t, 4> rgba{};  // sRGB bytes, as ReferenceImage::rgba holds them
  bool mirror = false;                 // ReferenceImage::mirrorMask: most primary rays hit a mirror
};

class PixelTracer {
 public:
  // `scene` must outlive the tracer and `posed` must be built from it; the camera and size must be valid
  // (RayTracer::pixelTracer checks them), `samples` must come from math::samplePattern.
  PixelTracer(const scene::Scene& scene, std::shared_ptr<const PosedScene> posed, const math::Camera& camera, int width,
              int height, int samples, int maxBounces);

  int width() const { return width_; }
  int height() const { return height_; }

  // Every sample ray of the pixel shaded and averaged. Safe to call from many threads.
  TracedPixel trace(int column, int row) const;
  // Only the primary rays: whether most of them hit a mirror (TracedPixel::mirror, far cheaper).
  bool seesMirror(int column, int row) const;

 private:
  const scene::Scene& scene_;
  std::shared_ptr<const PosedScene> posed_;
  SurfaceShader shader_;
  PrimaryRays rays_;
  int width_, height_, maxBounces_;
  float pixelAngle_;  // radians a pixel spans on the view axis: the spread of a pixel's ray cone
  std::span<const glm::vec2> samples_;
};

}  // namespace specula::reference
