#pragma once
// One client's session: protocol dispatch and validation, its state (camera, clock, overrides,
// settings), and the decision when it needs a frame. Messages arrive on the connection's strand;
// the scheduler's threads take render jobs and deliver encoded frames; a mutex guards the state.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "WireEncoding.h"
#include "net/Connection.h"
#include "session/AccuracyController.h"
#include "session/AccuracySampler.h"
#include "session/FrameRenderer.h"
#include "session/SessionState.h"

namespace specula::session {

class SessionHub;

// A render job plus what the frame message will say about it.
struct FrameRequest {
  RenderJob job;
  bool still = true;  // full quality; false while input keeps arriving
  int jpegQuality = 85;
  std::uint64_t inputSequence = 0;
  double clientTimeMs = 0.0;
  Clock::time_point inputArrival{};
  double sceneMs = 0.0;
  // Set on a still frame whose job is the last one rendered (a paused view after input): the
  // picture is that render's, only encoded again at still quality.
  std::shared_ptr<const RenderOutput> reuse;
  std::optional<std::size_t> accuracyRung;  // the accuracy target's setting rendered, when one is set
};

class Session : public net::ConnectionHandler, public std::enable_shared_from_this<Session> {
 public:
  Session(SessionHub& hub, std::shared_ptr<net::MessageSink> sink, protocol::Encoding encoding);

  // net::ConnectionHandler
  void onMessage(std::string_view payload, bool text) override;
  void onOversizedMessage() override;
  void onWriteTimedOut() override;
  void onFrameSent(std::size_t bytes) override;
  void onFrameReplaced() override;
  void onClosed() override;

  // Scheduler side. `due` says whether a frame should start now, else when to look again (nullopt:
  // not until something changes); `takeFrame` starts one, and the frame ends in deliver or renderFailed.
  struct Due {
    bool now = false;
    std::optional<Clock::time_point> wakeAt;
  };
  Due due(Clock::time_point now) const;
  FrameRequest takeFrame(Clock::time_point now);
  void deliver(const FrameRequest& request, std::shared_ptr<const RenderOutput> output, std::string jpeg,
               double encodeMs);
  void renderFailed(const FrameRequest& request, const std::string& message);
  // The accuracy sampler's result for a frame rendered under settings epoch `epoch`.
  void accuracyMeasured(std::uint64_t epoch, Result<FrameAccuracy> accuracy);

 private:
  void handle(const v1::ClientMessage& message, Clock::time_point now);
  void onHello(const v1::Hello& hello, Clock::time_point now);
  Status applyCamera(const v1::CameraUpdate& camera);
  Status applyAnimation(const v1::AnimationControl& animation, Clock::time_point now);
  Status applySettings(const v1::RenderSettings& settings);
  Status applyResize(const v1::Resize& resize);
  void restartAccuracyWindow();     // state_ locked
  void configureAccuracyControl();  // state_ locked: from the settings' accuracy target
  void noteInput(std::uint64_t sequence, double clientTimeMs, Clock::time_point now);  // state_ locked
  v1::Welcome welcome(bool resumed, Clock::time_point now) const;                      // state_ locked
  void send(const v1::ServerMessage& message);
  void sendError(v1::Error::Code code, const std::string& message);
  void closeForBadMessage(net::CloseCode code, v1::Error::Code errorCode, const std::string& message);

  SessionHub& hub_;
  const protocol::Encoding encoding_;
  const std::string id_;
  const std::uint64_t number_;  // process-unique, for renderer coherence
  std::string resumeToken_;

  mutable std::mutex mutex_;                // guards everything below
  std::shared_ptr<net::MessageSink> sink_;  // null once closed
  bool greeted_ = false;
  SessionState state_;
  bool dirty_ = false;            // something changed since the last frame started
  bool busy_ = false;             // a frame is being rendered or encoded
  bool settingsChanged_ = false;  // the next frame carries the settings, so clients show what is in effect
  bool lastFrameStill_ = true;
  std::optional<RenderJob> lastJob_;  // the last frame delivered and the render it showed
  std::shared_ptr<const RenderOutput> lastOutput_;
  bool renderBroken_ = false;  // the last render failed: wait for new input before retrying
  Clock::time_point lastInputAt_{};
  Clock::time_point lastFrameStart_{};
  std::uint64_t inputSequence_ = 0;
  double inputClientTimeMs_ = 0.0;
  Clock::time_point inputArrival_{};
  // Live accuracy: the latest estimate and the window since the settings last changed (a new epoch).
  std::uint64_t settingsEpoch_ = 0;
  std::uint64_t renderedFrame_ = 0;  // the last frame rendered (a re-encoded frame shows its pixels)
  std::optional<FrameAccuracy> latestAccuracy_;
  AccuracyWindow accuracyWindow_;
  std::optional<AccuracyController> accuracyControl_;  // with an accuracy target
  std::uint64_t framesStarted_ = 0, framesDelivered_ = 0, framesSent_ = 0, framesSkipped_ = 0, bytesSent_ = 0;
};

}  // namespace specula::session
