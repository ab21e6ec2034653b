#pragma once
// Admits WebSocket connections as sessions, shares the scene among them read-only, keeps resume
// states, counts metrics and owns the render scheduler.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "base/Result.h"
#include "net/Connection.h"
#include "scene/Scene.h"
#include "session/AccuracySampler.h"
#include "session/FrameRenderer.h"
#include "session/RenderScheduler.h"
#include "session/ResumeStore.h"
#include "session/ServiceMetrics.h"
#include "session/SignedResume.h"
#include "session/SessionState.h"

namespace specula::session {

class Session;

struct HubOptions {
  int maxSessions = 16;
  int maxWidth = 3840, maxHeight = 2160;      // viewport limits a hello or resize may ask for
  std::chrono::milliseconds stillDelay{150};  // quiet time after input before a full-quality still frame
  double maxFps = 60.0;                       // per session
  std::size_t maxMessageBytes = 64 * 1024;    // told to clients in Welcome.limits (net enforces it)
  std::size_t resumeCapacity = 1024;
  std::chrono::seconds resumeLifetime{600};
  // Non-empty: resume tokens are signed (SignedResume) and carry the state, so any instance with the
  // same secret resumes them; empty: this process keeps the states (ResumeStore).
  std::string resumeSecret;
  SessionSettings defaults;  // settings a new session starts with
  SchedulerOptions scheduler;
  // Trace a sample of every frame with the reference ray tracer (AccuracySampler) for the live
  // accuracy estimate; sessions choose how many pixels (SessionSettings::accuracySamples).
  bool estimateAccuracy = true;
};

class SessionHub : public net::ConnectionAcceptor {
 public:
  // Starts the render and encode threads; fails when a renderer cannot be created (no GL, shaders).
  static Result<std::unique_ptr<SessionHub>> start(std::shared_ptr<const scene::Scene> scene, HubOptions options,
                                                   FrameRendererFactory rendererFactory);
  ~SessionHub() override;

  std::shared_ptr<net::ConnectionHandler> accept(const net::UpgradeRequest& request,
                                                 std::shared_ptr<net::MessageSink> sink) override;

  // From now on new connections are refused with SHUTTING_DOWN and /readyz says "draining";
  // rendering continues for open ones.
  void refuseNewSessions();
  // Joins the render and encode threads and drops every session. Call after the network has stopped.
  void stop();

  const scene::Scene& scene() const { return *scene_; }
  const HubOptions& options() const { return options_; }
  ServiceMetrics& metrics() { return metrics_; }
  ResumeStore& resumeStore() { return resumes_; }
  AccuracySampler* accuracySampler() { return accuracy_.get(); }  // null when not estimating
  const SignedResume* signedResume() const { return signedResume_ ? &*signedResume_ : nullptr; }
  // Why this instance takes no new session now ("full", "draining"), or nullopt: GET /readyz.
  std::optional<std::string> notReady() const;
  // Metrics plus the hub's gauges: capacity, render queue depth, draining.
  std::string prometheusText() const;
  std::size_t sessionCount() const;
  // This process among its peers: "host:pid" (Welcome.instance).
  const std::string& instanceName() const { return instanceName_; }

  // Session callbacks.
  void sessionGreeted(const std::shared_ptr<Session>& session);
  void sessionClosed(Session& session, const std::string& resumeToken, std::optional<SessionState> state);
  void wakeScheduler();

 private:
  SessionHub(std::shared_ptr<const scene::Scene> scene, HubOptions options);

  std::shared_ptr<const scene::Scene> scene_;
  HubOptions options_;
  ServiceMetrics metrics_;
  ResumeStore resumes_;
  std::optional<SignedResume> signedResume_;
  std::unique_ptr<RenderScheduler> scheduler_;
  std::unique_ptr<AccuracySampler> accuracy_;
  mutable std::mutex mutex_;
  std::map<const Session*, std::shared_ptr<Session>> sessions_;
  bool refusing_ = false;
  std::string instanceName_;
};

}  // namespace specula::session
