#include "session/Session.h"

#include <atomic>
#include <cmath>
#include <utility>
#include <glm/gtc/quaternion.hpp>

#include "CameraConversions.h"
#include "ProtocolCodec.h"
#include "session/SessionHub.h"
#include "session/SettingsProtocol.h"
#include "session/SignedResume.h"

namespace specula::session {

namespace {

using protocol::toGlm;
using protocol::toProto;

constexpr std::uint32_t kProtocolVersion = 1;
constexpr float kMaxCoordinate = 1e7f;  // metres; beyond this float positions have no precision left
constexpr float kMaxSpeed = 16.0f;
constexpr double kMaxSceneMs = 1e12;

std::atomic<std::uint64_t> nextSessionNumber{1};

bool finiteWithin(const v1::Vec3& v, float bound) {
  for (float c : {v.x(), v.y(), v.z()})
    if (!std::isfinite(c) || std::abs(c) > bound) return false;
  return true;
}
double millisecondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

std::string checkViewport(std::uint32_t width, std::uint32_t height, const HubOptions& options) {
  if (width < 1 || height < 1 || width > static_cast<std::uint32_t>(options.maxWidth) ||
      height > static_cast<std::uint32_t>(options.maxHeight))
    return "viewport " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1x1.." +
           std::to_string(options.maxWidth) + "x" + std::to_string(options.maxHeight);
  return {};
}

}  // namespace

Session::Session(SessionHub& hub, std::shared_ptr<net::MessageSink> sink, protocol::Encoding encoding)
    : hub_(hub), encoding_(encoding), id_(randomToken()), number_(nextSessionNumber++), sink_(std::move(sink)) {
  state_.settings = hub.options().defaults;
  configureAccuracyControl();
}

void Session::send(const v1::ServerMessage& message) {
  std::shared_ptr<net::MessageSink> sink;
  {
    std::lock_guard lock(mutex_);
    sink = sink_;
  }
  if (sink) sink->sendControl(protocol::encodeServerMessage(message, encoding_));
}

void Session::sendError(v1::Error::Code code, const std::string& text) {
  v1::ServerMessage message;
  message.mutable_error()->set_code(code);
  message.mutable_error()->set_message(text);
  send(message);
}

void Session::closeForBadMessage(net::CloseCode code, v1::Error::Code errorCode, const std::string& text) {
  hub_.metrics().protocolErrors++;
  sendError(errorCode, text);
  std::shared_ptr<net::MessageSink> sink;
  {
    std::lock_guard lock(mutex_);
    sink = sink_;
  }
  if (sink) sink->close(code, text);
}

void Session::onMessage(std::string_view payload, bool text) {
  auto message = protocol::decodeClientMessage(payload, text, encoding_);
  if (!message) return closeForBadMessage(net::CloseCode::BadPayload, v1::Error::BAD_MESSAGE, message.error());
  handle(*message, Clock::now());
}

void Session::handle(const v1::ClientMessage& message, Clock::time_point now) {
  bool greeted;
  {
    std::lock_guard lock(mutex_);
    greeted = greeted_;
  }
  if (message.has_hello()) {
    if (greeted) return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::BAD_MESSAGE, "hello sent twice");
    return onHello(message.hello(), now);
  }
  if (!greeted)
    return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::BAD_MESSAGE,
                              "the first message must be hello (protocol version, viewport)");
  if (message.has_stats_request()) {
    v1::ServerMessage reply;
    v1::Stats& stats = *reply.mutable_stats();
    {
      std::lock_guard lock(mutex_);
      stats.set_frames_sent(framesSent_);
      stats.set_frames_skipped(framesSkipped_);
      stats.set_bytes_sent(bytesSent_);
      stats.set_scene_time_ms(state_.clock.sceneMs(now));
      stats.set_playing(state_.clock.playing());
    }
    stats.set_sessions(static_cast<std::uint32_t>(hub_.sessionCount()));
    return send(reply);
  }
  Status applied;
  std::uint64_t sequence = 0;
  double clientTimeMs = 0.0;
  if (message.has_camera()) {
    applied = applyCamera(message.camera());
    sequence = message.camera().sequence();
    clientTimeMs = message.camera().client_time_ms();
  } else if (message.has_animation()) {
    applied = applyAnimation(message.animation(), now);
    sequence = message.animation().sequence();
    clientTimeMs = message.animation().client_time_ms();
  } else if (message.has_settings()) {
    applied = applySettings(message.settings());
    sequence = message.settings().sequence();
    clientTimeMs = message.settings().client_time_ms();
  } else if (message.has_resize()) {
    applied = applyResize(message.resize());
    sequence = message.resize().sequence();
    clientTimeMs = message.resize().client_time_ms();
  }
  if (!applied) return sendError(v1::Error::BAD_VALUE, applied.error() + "; the message was ignored");
  {
    std::lock_guard lock(mutex_);
    noteInput(sequence, clientTimeMs, now);
  }
  hub_.wakeScheduler();
}

void Session::onHello(const v1::Hello& hello, Clock::time_point now) {
  const HubOptions& options = hub_.options();
  if (hello.protocol_version() != kProtocolVersion)
    return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::BAD_VALUE,
                              "protocol version " + std::to_string(hello.protocol_version()) +
                                  " is not spoken here: this server speaks version 1");
  if (!hello.scene().empty() && hello.scene() != hub_.scene().name)
    return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::UNKNOWN_SCENE,
                              "this server serves scene '" + hub_.scene().name + "', not '" + hello.scene() +
                                  "' (leave hello.scene empty for the server's scene)");
  if (std::string problem = checkViewport(hello.width(), hello.height(), options); !problem.empty())
    return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::BAD_VALUE, "hello: " + problem);
  if (hello.quality() > 100)
    return closeForBadMessage(net::CloseCode::PolicyViolation, v1::Error::BAD_VALUE,
                              "hello: quality must be 1..100 (or 0 for the default)");
  std::optional<SessionState> restored;
  std::string refusal;  // why the hello's token did not resume, told after the welcome
  if (!hello.resume_token().empty()) {
    if (const SignedResume* signedResume = hub_.signedResume()) {
      Result<SessionState> opened = signedResume->open(hello.resume_token(), options.defaults, now, WallClock::now());
      if (opened) restored = std::move(opened.value());
      else refusal = opened.error();
    } else {
      if (hello.resume_token().size() <= 64) restored = hub_.resumeStore().take(hello.resume_token(), now);
      if (!restored)
        refusal = "resume token refused: this instance does not know it (tokens are kept " +
                  std::to_string(options.resumeLifetime.count()) +
                  " s and resume once; instances share none without --resume-secret-file)";
    }
  }
  v1::ServerMessage reply;
  {
    std::lock_guard lock(mutex_);
    if (restored) {
      state_ = std::move(*restored);
      configureAccuracyControl();
      if (state_.playOnResume) state_.clock.play(now);
    } else if (hub_.scene().moves()) {
      state_.clock.play(now);  // a moving scene moves from the start
    }
    state_.width = static_cast<int>(hello.width());
    state_.height = static_cast<int>(hello.height());
    if (hello.quality() > 0) state_.settings.jpegQuality = static_cast<int>(hello.quality());
    greeted_ = true;
    dirty_ = true;
    const SignedResume* signedResume = hub_.signedResume();
    resumeToken_ = signedResume ? signedResume->issue(state_, now, WallClock::now()) : randomToken();
    *reply.mutable_welcome() = welcome(restored.has_value(), now);
  }
  send(reply);
  if (!refusal.empty()) {
    hub_.metrics().resumesRefused++;
    sendError(v1::Error::RESUME_REFUSED, refusal + "; this is a fresh session");
  }
  if (restored) hub_.metrics().sessionsResumed++;
  hub_.sessionGreeted(shared_from_this());
}

v1::Welcome Session::welcome(bool resumed, Clock::time_point now) const {
  const HubOptions& options = hub_.options();
  const scene::Scene& scene = hub_.scene();
  v1::Welcome out;
  out.set_protocol_version(kProtocolVersion);
  out.set_session_id(id_);
  out.set_resume_token(resumeToken_);
  out.set_resumed(resumed);
  v1::SceneInfo& info = *out.mutable_scene();
  info.set_name(scene.name);
  for (const scene::SceneObject& object : scene.objects) info.add_objects(object.name);
  info.set_mirrors(static_cast<std::uint32_t>(scene.mirrorCount()));
  info.set_triangles(scene.triangleCount());
  *info.mutable_eye() = toProto(scene.camera.eye);
  *info.mutable_target() = toProto(scene.camera.target);
  *info.mutable_up() = toProto(scene.camera.up);
  info.set_fov_degrees(scene.camera.fovYDegrees);
  info.set_animated(scene.moves());
  for (const std::string& note : scene.notes) info.add_notes(note);
  v1::Limits& limits = *out.mutable_limits();
  limits.set_max_message_bytes(static_cast<std::uint32_t>(options.maxMessageBytes));
  limits.set_max_width(static_cast<std::uint32_t>(options.maxWidth));
  limits.set_max_height(static_cast<std::uint32_t>(options.maxHeight));
  limits.set_max_sessions(static_cast<std::uint32_t>(options.maxSessions));
  limits.set_still_delay_ms(static_cast<double>(options.stillDelay.count()));
  const double sceneMs = state_.clock.sceneMs(now);
  const math::Camera camera = state_.camera ? *state_.camera : scene::ScenePose::at(scene, sceneMs / 1000.0).camera;
  *out.mutable_camera() = protocol::cameraUpdate(camera.eye, camera.target, camera.up, camera.fovYDegrees);
  *out.mutable_settings() = settingsToProto(state_.settings);
  out.set_playing(state_.clock.playing());
  out.set_scene_time_ms(sceneMs);
  out.set_speed(state_.clock.speed());
  out.set_instance(hub_.instanceName());
  return out;
}

Status Session::applyCamera(const v1::CameraUpdate& update) {
  if (!update.has_eye() || !update.has_target()) return Error{"camera: eye and target are required"};
  for (const auto& [name, vector] :
       {std::pair{"eye", &update.eye()}, {"target", &update.target()}, {"up", &update.up()}})
    if (!finiteWithin(*vector, kMaxCoordinate))
      return Error{std::string("camera: ") + name + " must be finite and within 1e7 m of the origin"};
  std::lock_guard lock(mutex_);
  math::Camera camera = state_.camera.value_or(hub_.scene().camera);
  camera.eye = toGlm(update.eye());
  camera.target = toGlm(update.target());
  if (update.has_up()) camera.up = toGlm(update.up());
  if (update.fov_degrees() != 0.0f) camera.fovYDegrees = update.fov_degrees();
  if (auto problem = math::cameraProblem(camera)) return Error{"camera: " + *problem};
  state_.camera = camera;
  return {};
}

Status Session::applyAnimation(const v1::AnimationControl& control, Clock::time_point now) {
  const scene::Scene& scene = hub_.scene();
  if (!std::isfinite(control.speed()) || std::abs(control.speed()) > kMaxSpeed)
    return Error{"animation: speed must be within [-16, 16]"};
  if (control.action() == v1::AnimationControl::SEEK &&
      (!std::isfinite(control.time_ms()) || std::abs(control.time_ms()) > kMaxSceneMs))
    return Error{"animation: time_ms must be finite and within ±1e12"};
  if (control.overrides_size() > static_cast<int>(scene.objects.size()))
    return Error{"animation: more overrides than the scene has objects"};
  std::map<std::uint32_t, std::optional<glm::mat4>> changes;  // nullopt clears
  for (const v1::ObjectTransform& item : control.overrides()) {
    std::uint32_t index = 0;
    while (index < scene.objects.size() && scene.objects[index].name != item.object()) ++index;
    if (index == scene.objects.size())
      return Error{"animation: no object named '" + item.object().substr(0, 64) +
                   "' (Welcome.scene.objects lists them)"};
    if (item.clear()) {
      changes[index] = std::nullopt;
      continue;
    }
    if (!finiteWithin(item.translation(), kMaxCoordinate) || !finiteWithin(item.rotation_axis(), 1e6f) ||
        !finiteWithin(item.scale(), 1e6f) || !std::isfinite(item.rotation_degrees()))
      return Error{"animation: override of '" + item.object() + "' has a non-finite or huge value"};
    math::Transform transform;
    transform.translation = toGlm(item.translation());
    const glm::vec3 axis = toGlm(item.rotation_axis());
    if (glm::length(axis) > 1e-6f)
      transform.rotation = glm::angleAxis(glm::radians(item.rotation_degrees()), glm::normalize(axis));
    const glm::vec3 scale = toGlm(item.scale());
    if (scale != glm::vec3(0.0f)) {
      if (scale.x <= 0.0f || scale.y <= 0.0f || scale.z <= 0.0f)
        return Error{"animation: override of '" + item.object() + "' needs a positive scale (or zero for 1)"};
      transform.scale = scale;
    }
    changes[index] = transform.matrix();
  }
  std::lock_guard lock(mutex_);
  std::size_t overridden = state_.overrides.size();
  for (const auto& [index, matrix] : changes) overridden += matrix && !state_.overrides.contains(index) ? 1 : 0;
  if (overridden > SignedResume::kMaxOverrides)
    return Error{"animation: at most " + std::to_string(SignedResume::kMaxOverrides) +
                 " objects can be overridden at once; clear some first"};
  if (control.speed() != 0.0f) state_.clock.setSpeed(control.speed(), now);
  if (control.action() == v1::AnimationControl::PLAY) state_.clock.play(now);
  if (control.action() == v1::AnimationControl::PAUSE) state_.clock.pause(now);
  if (control.action() == v1::AnimationControl::SEEK) state_.clock.seek(control.time_ms(), now);
  for (const auto& [index, matrix] : changes) {
    if (matrix) state_.overrides[index] = *matrix;
    else state_.overrides.erase(index);
  }
  return {};
}

Status Session::applySettings(const v1::RenderSettings& update) {
  std::lock_guard lock(mutex_);
  const SessionSettings before = state_.settings;
  Status applied = applySettingsUpdate(update, state_.settings);
  if (applied && state_.settings.accuracyTarget > 0.0f && state_.settings.accuracySamples == 0) {
    state_.settings = before;
    return Error{
        "settings: accuracy_target needs the live estimate: set accuracy_samples above 0, or "
        "accuracy_target to -1 (off)"};
  }
  settingsChanged_ = settingsChanged_ || applied;
  if (applied && !(state_.settings == before)) {  // estimates of frames rendered before judge other settings
    restartAccuracyWindow();
    configureAccuracyControl();
  }
  return applied;
}

void Session::configureAccuracyControl() {
  if (state_.settings.accuracyTarget > 0.0f && state_.settings.accuracySamples > 0)
    accuracyControl_.emplace(accuracyLadder(state_.settings.reflection), state_.settings.accuracyTarget / 100.0);
  else accuracyControl_.reset();
}

void Session::restartAccuracyWindow() {
  ++settingsEpoch_;
  latestAccuracy_.reset();
  accuracyWindow_.clear();
}

Status Session::applyResize(const v1::Resize& resize) {
  if (std::string problem = checkViewport(resize.width(), resize.height(), hub_.options()); !problem.empty())
    return Error{"resize: " + problem};
  std::lock_guard lock(mutex_);
  state_.width = static_cast<int>(resize.width());
  state_.height = static_cast<int>(resize.height());
  return {};
}

void Session::noteInput(std::uint64_t sequence, double clientTimeMs, Clock::time_point now) {
  dirty_ = true;
  renderBroken_ = false;
  lastInputAt_ = now;
  inputSequence_ = std::max(inputSequence_, sequence);
  inputClientTimeMs_ = clientTimeMs;
  inputArrival_ = now;
}

Session::Due Session::due(Clock::time_point now) const {
  std::lock_guard lock(mutex_);
  if (!greeted_ || busy_ || !sink_ || renderBroken_) return {};
  const bool settled = now - lastInputAt_ >= hub_.options().stillDelay;
  const bool wantsStill = !lastFrameStill_;
  if (!dirty_ && !state_.clock.playing() && !wantsStill) return {};
  if (!dirty_ && !state_.clock.playing() && !settled) return {false, lastInputAt_ + hub_.options().stillDelay};
  const auto earliest = lastFrameStart_ + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(1.0 / hub_.options().maxFps));
  if (framesStarted_ > 0 && now < earliest) return {false, earliest};
  return {true, std::nullopt};
}

FrameRequest Session::takeFrame(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  const scene::Scene& scene = hub_.scene();
  FrameRequest request;
  request.still = now - lastInputAt_ >= hub_.options().stillDelay;
  request.jpegQuality = request.still ? state_.settings.jpegQuality : state_.settings.interactiveQuality;
  request.inputSequence = inputSequence_;
  request.clientTimeMs = inputClientTimeMs_;
  request.inputArrival = inputArrival_ == Clock::time_point{} ? now : inputArrival_;
  request.sceneMs = state_.clock.sceneMs(now);
  request.job.session = number_;
  request.job.pose = scene::ScenePose::at(scene, request.sceneMs / 1000.0);
  for (const auto& [index, matrix] : state_.overrides) request.job.pose.objectToWorld[index] = matrix;
  if (state_.camera) request.job.pose.camera = *state_.camera;
  std::tie(request.job.width, request.job.height) = state_.renderSize();
  request.job.settings = state_.settings.reflection;
  if (accuracyControl_) {
    request.job.settings = accuracyControl_->current().settings;
    request.accuracyRung = accuracyControl_->rung();
  }
  request.job.samples = request.still ? state_.settings.stillSamples : state_.settings.interactiveSamples;
  if (request.still && lastOutput_ && lastJob_ == request.job) request.reuse = lastOutput_;
  dirty_ = false;
  busy_ = true;
  lastFrameStill_ = request.still;
  lastFrameStart_ = now;
  ++framesStarted_;
  return request;
}

namespace {

v1::AccuracyEstimate accuracyEstimate(const FrameAccuracy& latest, const AccuracyWindow& window) {
  v1::AccuracyEstimate out;
  const reference::ShareEstimate& frame = latest.sample.mismatch;
  out.set_frame(latest.frame);
  out.set_sampled(static_cast<std::uint32_t>(frame.sampled));
  out.set_mismatched(static_cast<std::uint32_t>(frame.hits));
  out.set_mismatch(frame.share());
  out.set_low(frame.low);
  out.set_high(frame.high);
  const reference::ShareEstimate pooled = window.pooled();
  out.set_window_frames(static_cast<std::uint32_t>(window.frames()));
  out.set_window_sampled(pooled.sampled);
  out.set_window_mismatch(pooled.share());
  out.set_window_low(pooled.low);
  out.set_window_high(pooled.high);
  out.set_trace_ms(latest.milliseconds);
  out.set_probed(static_cast<std::uint32_t>(latest.sample.probedPixels));
  return out;
}

}  // namespace

void Session::deliver(const FrameRequest& request, std::shared_ptr<const RenderOutput> rendered, std::string jpeg,
                      double encodeMs) {
  const RenderOutput& output = *rendered;
  const bool reencoded = request.reuse != nullptr;
  const Clock::time_point now = Clock::now();
  v1::ServerMessage message;
  v1::Frame& frame = *message.mutable_frame();
  frame.set_input_sequence(request.inputSequence);
  frame.set_client_time_ms(request.clientTimeMs);
  frame.set_scene_time_ms(request.sceneMs);
  frame.set_width(static_cast<std::uint32_t>(output.width));
  frame.set_height(static_cast<std::uint32_t>(output.height));
  frame.set_still(request.still);
  frame.set_reencoded(reencoded);
  if (!reencoded) {  // a re-encoded frame ran no pass
    for (const auto& [name, ms] : output.stageMs) {
      v1::StageTime& stage = *frame.add_stages();
      stage.set_name(name);
      stage.set_ms(ms);
    }
    frame.set_render_ms(output.renderMs);
  }
  frame.set_encode_ms(encodeMs);
  const double serverMs = millisecondsBetween(request.inputArrival, now);
  frame.set_server_ms(serverMs);
  *frame.mutable_search() = output.search;
  *frame.mutable_tessellation() = output.tessellation;
  for (const v1::MirrorPlan& mirror : output.plan) *frame.add_plan() = mirror;
  frame.set_jpeg(std::move(jpeg));
  const math::Camera& camera = request.job.pose.camera;
  *frame.mutable_camera() = protocol::cameraUpdate(camera.eye, camera.target, camera.up, camera.fovYDegrees);
  std::shared_ptr<net::MessageSink> sink;
  std::optional<AccuracyJob> accuracyJob;
  std::uint64_t epoch = 0;
  {
    std::lock_guard lock(mutex_);
    busy_ = false;
    lastJob_ = request.job;
    lastOutput_ = std::move(rendered);
    frame.set_number(++framesDelivered_);
    frame.set_skipped_frames(framesSkipped_);
    if (latestAccuracy_) *frame.mutable_accuracy() = accuracyEstimate(*latestAccuracy_, accuracyWindow_);
    if (accuracyControl_) {
      if (request.accuracyRung && !reencoded) accuracyControl_->frameRendered(*request.accuracyRung, output.renderMs);
      v1::AccuracyControl& control = *frame.mutable_accuracy_control();
      control.set_target(100.0f * static_cast<float>(accuracyControl_->target()));
      control.set_setting(accuracyControl_->current().name);
      control.set_reason(accuracyControl_->reason());
      control.set_met(accuracyControl_->met());
    }
    if (!reencoded) renderedFrame_ = frame.number();
    if (!reencoded && state_.settings.accuracySamples > 0)
      accuracyJob = AccuracyJob{frame.number(), request.job.pose, request.job.samples, state_.settings.accuracySamples,
                                lastOutput_};
    epoch = settingsEpoch_;
    if (std::exchange(settingsChanged_, false)) *frame.mutable_settings() = settingsToProto(state_.settings);
    if (const SignedResume* signedResume = hub_.signedResume())
      frame.set_resume_token(signedResume->issue(state_, now, WallClock::now()));
    sink = sink_;
  }
  ServiceMetrics& metrics = hub_.metrics();
  if (!reencoded) metrics.renderMs.observe(output.renderMs);
  metrics.encodeMs.observe(encodeMs);
  metrics.latencyMs.observe(serverMs);
  if (sink) {
    std::string payload = protocol::encodeServerMessage(message, encoding_);
    metrics.frameBytes.observe(static_cast<double>(payload.size()));
    sink->sendFrame(std::move(payload));
  }
  if (AccuracySampler* sampler = hub_.accuracySampler(); sampler && accuracyJob && sink)
    sampler->submit(this, std::move(*accuracyJob), [weak = weak_from_this(), epoch](Result<FrameAccuracy> accuracy) {
      if (auto session = weak.lock()) session->accuracyMeasured(epoch, std::move(accuracy));
    });
  hub_.wakeScheduler();
}

void Session::accuracyMeasured(std::uint64_t epoch, Result<FrameAccuracy> accuracy) {
  ServiceMetrics& metrics = hub_.metrics();
  if (!accuracy) {
    metrics.accuracyFailures++;
    return;
  }
  metrics.accuracyMismatch.observe(100.0 * accuracy->sample.mismatch.share());
  metrics.accuracyMs.observe(accuracy->milliseconds);
  v1::ServerMessage message;
  bool rendersAgain = false;
  {
    std::lock_guard lock(mutex_);
    if (epoch != settingsEpoch_) return;
    accuracyWindow_.add(*accuracy);
    latestAccuracy_ = std::move(*accuracy);
    if (accuracyControl_ &&
        accuracyControl_->windowMeasured(accuracyWindow_.pooled(), accuracyWindow_.frames(), framesDelivered_)) {
      restartAccuracyWindow();  // another setting: its own window, and a frame of it
      dirty_ = true;
      rendersAgain = true;
    }
    // A still view sends no further frame to carry it.
    const bool onScreen = !rendersAgain && latestAccuracy_ && latestAccuracy_->frame == renderedFrame_ && !busy_ &&
                          !dirty_ && !state_.clock.playing();
    if (onScreen) *message.mutable_accuracy() = accuracyEstimate(*latestAccuracy_, accuracyWindow_);
  }
  if (rendersAgain) hub_.wakeScheduler();
  if (message.has_accuracy()) send(message);
}

void Session::renderFailed(const FrameRequest&, const std::string& text) {
  {
    std::lock_guard lock(mutex_);
    busy_ = false;
    renderBroken_ = true;  // no retry loop: the next input tries again
  }
  hub_.metrics().renderFailures++;
  sendError(v1::Error::RENDER_FAILED, "the frame could not be rendered: " + text);
}

void Session::onOversizedMessage() { hub_.metrics().protocolErrors++; }
void Session::onWriteTimedOut() { hub_.metrics().writeTimeouts++; }

void Session::onFrameSent(std::size_t bytes) {
  {
    std::lock_guard lock(mutex_);
    ++framesSent_;
    bytesSent_ += bytes;
  }
  hub_.metrics().framesSent++;
  hub_.metrics().frameBytesSent += bytes;
}

void Session::onFrameReplaced() {
  {
    std::lock_guard lock(mutex_);
    ++framesSkipped_;
  }
  hub_.metrics().framesSkipped++;
}

void Session::onClosed() {
  if (AccuracySampler* sampler = hub_.accuracySampler()) sampler->forget(this);
  std::optional<SessionState> saved;
  std::string token;
  {
    std::lock_guard lock(mutex_);
    sink_.reset();
    if (greeted_ && !hub_.signedResume()) saved = state_;  // signed tokens carry the state themselves
    token = resumeToken_;
  }
  if (saved) {  // freeze scene time at the disconnect; a resume continues from here, not from wall time
    saved->playOnResume = saved->clock.playing();
    saved->clock.pause(Clock::now());
  }
  hub_.sessionClosed(*this, token, std::move(saved));
}

}  // namespace specula::session
