#pragma once
// What a session controls, as plain data: saved for resume and snapshotted for each render.
#include <cstdint>
#include <map>
#include <optional>

#include <glm/glm.hpp>

#include "math/Camera.h"
#include "math/SamplePattern.h"
#include "passes/ReflectionSettings.h"
#include "reference/MismatchSample.h"
#include "session/AnimationClock.h"

namespace specula::session {

struct SessionSettings {
  passes::ReflectionSettings reflection;
  float resolutionScale = 1.0f;                 // (0, 1]: frames are rendered this much smaller
  int jpegQuality = 85;                         // still frames
  int interactiveQuality = 60;                  // frames sent while input keeps arriving
  int stillSamples = math::kStillFrameSamples;  // anti-aliasing (math::samplePattern) of still frames
  int interactiveSamples = 1;                   // and of frames sent while input keeps arriving
  // Mirror pixels a frame the live accuracy estimate traces exactly (AccuracySampler); 0: none.
  int accuracySamples = reference::kDefaultAccuracySamples;
  // Percent of mirror pixels: render the cheapest setting whose live estimate stays under it
  // (AccuracyController); 0: render the reflection settings as given.
  float accuracyTarget = 0.0f;

  bool operator==(const SessionSettings&) const = default;
};

struct SessionState {
  int width = 0, height = 0;           // the client's viewport
  std::optional<math::Camera> camera;  // nullopt: the scene's own (possibly animated) camera
  AnimationClock clock;
  std::map<std::uint32_t, glm::mat4> overrides;  // object index → object-to-world, replacing the animation
  SessionSettings settings;
  bool playOnResume = false;  // saved sessions: whether the (paused) clock plays again on resume

  // The frame size to render: the viewport times the resolution scale, at least 1×1.
  std::pair<int, int> renderSize() const;
};

}  // namespace specula::session
