#pragma once
// The live accuracy estimate of streamed frames: a worker thread traces a sample of each frame's
// mirror pixels with the reference ray tracer (reference::sampleMirrorMismatch) beside rendering, at the
// lowest CPU priority, so estimating never delays a frame; a frame's estimate arrives with a later one,
// and on a machine the renderer keeps busy fewer frames are estimated.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "base/Result.h"
#include "reference/MismatchSample.h"
#include "scene/Scene.h"
#include "scene/ScenePose.h"
#include "session/FrameRenderer.h"

namespace specula::reference {
class PosedScene;
class RayTracer;
}  // namespace specula::reference

namespace specula::session {

struct AccuracyJob {
  std::uint64_t frame = 0;  // the session's frame number, echoed in the result
  scene::ScenePose pose;    // the frame's pose and camera
  int samples = 1;          // the frame's anti-aliasing: the exact pixels are traced alike
  int pixels = reference::kDefaultAccuracySamples;
  std::shared_ptr<const RenderOutput> output;  // the frame's pixels, as encoded
};

struct FrameAccuracy {
  std::uint64_t frame = 0;
  reference::MismatchSample sample;
  double milliseconds = 0.0;  // the worker thread's CPU time on it
};

class AccuracySampler {
 public:
  using Done = std::function<void(Result<FrameAccuracy>)>;

  // Creates the reference tracer (an Embree device) and starts the worker.
  static Result<std::unique_ptr<AccuracySampler>> start(std::shared_ptr<const scene::Scene> scene);
  ~AccuracySampler();  // stop()

  // Queues `job` for `owner`, replacing that owner's job not yet started (the newer frame wins);
  // `done` runs on the worker thread.
  void submit(const void* owner, AccuracyJob job, Done done);
  // Drops the owner's waiting job (a closing session); a job already started still calls its `done`.
  void forget(const void* owner);
  void stop();  // joins the worker; waiting jobs are dropped

 private:
  struct Pending {
    const void* owner;
    AccuracyJob job;
    Done done;
  };
  AccuracySampler() = default;
  void work();
  Result<FrameAccuracy> estimate(const AccuracyJob& job);

  std::unique_ptr<reference::RayTracer> tracer_;
  // The last pose's geometry, reused while objects stay put (a moving camera does not change it).
  std::shared_ptr<const reference::PosedScene> posed_;
  scene::ScenePose posedFor_;

  std::mutex mutex_;  // guards pending_ and stopping_
  std::condition_variable ready_;
  std::deque<Pending> pending_;
  bool stopping_ = false;
  std::thread worker_;
};

// The estimates of a session's last frames pooled: the window a viewer and the accuracy target read.
class AccuracyWindow {
 public:
  static constexpr std::size_t kFrames = 30;

  void add(const FrameAccuracy& frame);
  void clear() { frames_.clear(); }
  std::size_t frames() const { return frames_.size(); }
  reference::ShareEstimate pooled() const;  // every sampled pixel of the window's frames

 private:
  std::deque<reference::ShareEstimate> frames_;
};

}  // namespace specula::session
