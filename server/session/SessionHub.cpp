#include "session/SessionHub.h"

#include <unistd.h>

#include "ProtocolCodec.h"
#include "session/Session.h"

namespace specula::session {

SessionHub::SessionHub(std::shared_ptr<const scene::Scene> scene, HubOptions options)
    : scene_(std::move(scene)),
      options_(std::move(options)),
      resumes_(options_.resumeCapacity, options_.resumeLifetime) {
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  instanceName_ = std::string(host) + ":" + std::to_string(getpid());
}

SessionHub::~SessionHub() { stop(); }

Result<std::unique_ptr<SessionHub>> SessionHub::start(std::shared_ptr<const scene::Scene> scene, HubOptions options,
                                                      FrameRendererFactory rendererFactory) {
  std::unique_ptr<SessionHub> hub(new SessionHub(std::move(scene), std::move(options)));
  if (!hub->options_.resumeSecret.empty()) {
    auto signedResume = SignedResume::create(hub->options_.resumeSecret, hub->options_.resumeLifetime, *hub->scene_);
    if (!signedResume) return Error{signedResume.error()};
    hub->signedResume_.emplace(std::move(signedResume.value()));
  }
  if (hub->options_.estimateAccuracy) {
    auto sampler = AccuracySampler::start(hub->scene_);
    if (!sampler) return Error{sampler.error()};
    hub->accuracy_ = std::move(*sampler);
  }
  auto scheduler = RenderScheduler::start(std::move(rendererFactory), hub->options_.scheduler);
  if (!scheduler) return Error{scheduler.error()};
  hub->scheduler_ = std::move(*scheduler);
  return hub;
}

std::shared_ptr<net::ConnectionHandler> SessionHub::accept(const net::UpgradeRequest& request,
                                                           std::shared_ptr<net::MessageSink> sink) {
  auto refuse = [&](v1::Error::Code code, net::CloseCode closeCode, const std::string& text) {
    metrics_.sessionsRefused++;
    v1::ServerMessage message;
    message.mutable_error()->set_code(code);
    message.mutable_error()->set_message(text);
    sink->sendControl(protocol::encodeServerMessage(message, request.encoding));
    sink->close(closeCode, text);
    return nullptr;
  };
  std::lock_guard lock(mutex_);
  if (refusing_) return refuse(v1::Error::SHUTTING_DOWN, net::CloseCode::GoingAway, "the server is shutting down");
  if (sessions_.size() >= static_cast<std::size_t>(options_.maxSessions))
    return refuse(v1::Error::SERVER_FULL, net::CloseCode::TryAgainLater,
                  "the server is full (" + std::to_string(options_.maxSessions) +
                      " sessions, its --max-sessions): try again later");
  auto session = std::make_shared<Session>(*this, std::move(sink), request.encoding);
  sessions_[session.get()] = session;
  metrics_.sessions++;
  return session;
}

void SessionHub::refuseNewSessions() {
  std::lock_guard lock(mutex_);
  refusing_ = true;
}

void SessionHub::stop() {
  if (scheduler_) scheduler_->stop();
  if (accuracy_) accuracy_->stop();
  std::map<const Session*, std::shared_ptr<Session>> dropped;
  {
    std::lock_guard lock(mutex_);
    refusing_ = true;
    dropped.swap(sessions_);
  }
}

std::optional<std::string> SessionHub::notReady() const {
  std::lock_guard lock(mutex_);
  if (refusing_) return "draining";
  if (sessions_.size() >= static_cast<std::size_t>(options_.maxSessions)) return "full";
  return std::nullopt;
}

std::string SessionHub::prometheusText() const {
  bool draining = false;
  {
    std::lock_guard lock(mutex_);
    draining = refusing_;
  }
  std::string out = metrics_.prometheusText();
  net::appendPrometheusSample(out, "specula_sessions_capacity", "gauge",
                              "Sessions this instance admits (--max-sessions).",
                              static_cast<double>(options_.maxSessions));
  net::appendPrometheusSample(out, "specula_render_queue_depth", "gauge",
                              "Sessions due a frame that wait for a render worker.",
                              static_cast<double>(scheduler_ ? scheduler_->waitingSessions() : 0));
  net::appendPrometheusSample(out, "specula_draining", "gauge",
                              "1 while the instance refuses new sessions before it stops.", draining ? 1.0 : 0.0);
  return out;
}

std::size_t SessionHub::sessionCount() const {
  std::lock_guard lock(mutex_);
  return sessions_.size();
}

void SessionHub::sessionGreeted(const std::shared_ptr<Session>& session) {
  metrics_.sessionsOpened++;
  if (scheduler_) scheduler_->add(session);
}

void SessionHub::sessionClosed(Session& session, const std::string& resumeToken, std::optional<SessionState> state) {
  if (state) resumes_.save(resumeToken, std::move(*state), Clock::now());
  if (scheduler_) scheduler_->remove(&session);
  std::shared_ptr<Session> keepAlive;  // released outside the lock: the session may be destroyed with it
  {
    std::lock_guard lock(mutex_);
    auto found = sessions_.find(&session);
    if (found == sessions_.end()) return;
    keepAlive = std::move(found->second);
    sessions_.erase(found);
  }
  metrics_.sessions--;
}

void SessionHub::wakeScheduler() {
  if (scheduler_) scheduler_->wake();
}

}  // namespace specula::session
