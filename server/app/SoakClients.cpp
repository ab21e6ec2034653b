#include "app/SoakClients.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "OrbitCamera.h"

namespace specula::app {

namespace {

// A cycle of complete settings, so every state comes back and its GL resources can be reused: methods,
// search strategies and render sizes (resolution scale) that allocate different passes and targets.
v1::ClientMessage settingsMessage(std::size_t index) {
  v1::ClientMessage message;
  v1::RenderSettings& settings = *message.mutable_settings();
  switch (index % 4) {
    case 0:
      settings.set_method(v1::SEARCH);
      settings.set_search(v1::SEARCH_CROSSHAIR);
      settings.set_resolution_scale(1.0f);
      settings.set_jpeg_quality(85);
      break;
    case 1:
      settings.set_method(v1::ENVIRONMENT_MAP);
      settings.set_resolution_scale(0.5f);
      settings.set_jpeg_quality(60);
      break;
    case 2:
      settings.set_method(v1::SEARCH);
      settings.set_search(v1::SEARCH_HIERARCHY);
      settings.set_resolution_scale(0.75f);
      settings.set_interactive_quality(40);
      break;
    default:
      settings.set_method(v1::NONE);
      settings.set_resolution_scale(1.0f);
      settings.set_interactive_quality(70);
      break;
  }
  settings.set_sequence(index + 1);
  settings.set_client_time_ms(client::steadyMilliseconds());
  return message;
}

void sleepSeconds(double seconds) {
  if (seconds > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

// Reads nothing for `seconds` but keeps moving the camera, so frames for it keep coming: the server
// must replace them (latest wins) and drop the connection once a write waits past its deadline, not queue them.
Status stopReading(client::ResumingClient& client, double seconds) {
  client::OrbitCamera orbit;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
    orbit.orbit(0.05f, 0.0f);
    if (Status sent = client.send(orbit.message(0, client::steadyMilliseconds())); !sent) return sent;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return {};
}

}  // namespace

std::string roleName(SoakRole role) {
  switch (role) {
    case SoakRole::Steady: return "steady";
    case SoakRole::SlowReader: return "slow reader";
    case SoakRole::Stopper: return "stops reading";
    case SoakRole::Vanisher: return "vanishes";
    case SoakRole::SettingsChanger: return "changes settings";
  }
  return "?";
}

SoakClients::SoakClients(int sessions, SoakTiming timing)
    : timing_(timing), states_(static_cast<std::size_t>(std::max(0, sessions))) {
  // Sessions of one role take turns: their events are spread over the role's period.
  for (std::size_t i = 0; i < states_.size(); ++i) {
    const double phase = static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(1, states_.size()));
    switch (role(static_cast<int>(i))) {
      case SoakRole::Stopper: states_[i].nextEvent = (0.5 + phase) * timing_.stopEverySeconds; break;
      case SoakRole::Vanisher: states_[i].nextEvent = (0.5 + phase) * timing_.vanishEverySeconds; break;
      case SoakRole::SettingsChanger: states_[i].nextEvent = phase * timing_.settingsEverySeconds; break;
      default: break;
    }
  }
}

client::ReconnectPolicy SoakClients::connection(int session, client::ReconnectPolicy policy) const {
  if (role(session) == SoakRole::Stopper) policy.receiveBufferBytes = timing_.stopperReceiveBufferBytes;
  return policy;
}

Status SoakClients::act(int session, double seconds, client::ResumingClient& client) {
  SessionState& state = states_.at(static_cast<std::size_t>(session));
  const double nextStorm =
      timing_.runSeconds * static_cast<double>(state.stormsJoined + 1) / static_cast<double>(timing_.storms + 1);
  if (state.stormsJoined < timing_.storms && seconds >= nextStorm) {
    ++state.stormsJoined;
    ++drops_;
    client.drop();  // every session at once: the server sees a burst of resets, then of resuming hellos
    return {};
  }
  const SoakRole role = this->role(session);
  if (role == SoakRole::SlowReader) sleepSeconds(timing_.slowReadPauseSeconds);
  if (seconds < state.nextEvent) return {};
  switch (role) {
    case SoakRole::Stopper: {
      ++stops_;
      state.nextEvent = seconds + timing_.stopEverySeconds;
      // A stopper drops nothing itself: a reconnect while it stopped is the server dropping it.
      const int reconnectsBefore = client.reconnects();
      Status stopped = stopReading(client, std::min(timing_.stopForSeconds, timing_.runSeconds - seconds - 1.0));
      if (client.reconnects() > reconnectsBefore) ++stopsDropped_;
      return stopped;
    }
    case SoakRole::Vanisher:
      ++drops_;
      client.drop();  // frames keep streaming to it, so the reset usually lands mid-frame
      state.nextEvent = seconds + timing_.vanishEverySeconds;
      return {};
    case SoakRole::SettingsChanger:
      ++settingsSent_;
      state.nextEvent = seconds + timing_.settingsEverySeconds;
      return client.send(settingsMessage(state.settingsIndex++));
    default: return {};
  }
}

SoakActions SoakClients::actions() const {
  int storms = 0;
  for (const SessionState& state : states_) storms = std::max(storms, state.stormsJoined);
  return {storms, drops_.load(), stops_.load(), settingsSent_.load(), stopsDropped_.load()};
}

}  // namespace specula::app
