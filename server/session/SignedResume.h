#pragma once
// Stateless resume (issue #21): a token that carries the session's state (viewport, camera,
// animation time, playing and speed, object overrides, render settings) and when it expires,
// authenticated with HMAC-SHA256 under a secret the instances share. Any instance holding the secret
// resumes any instance's session, so a client whose instance dies, drains or is rescheduled
// reconnects through the balancer and keeps its view. The token is readable (base64url protobuf,
// v1::ResumeState): it holds the state and nothing else.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "base/Result.h"
#include "scene/Scene.h"
#include "session/SessionState.h"

namespace specula::session {

using WallClock = std::chrono::system_clock;

class SignedResume {
 public:
  static constexpr std::size_t kMinSecretBytes = 32;
  static constexpr std::size_t kMaxTokenBytes = 32 * 1024;  // a hello stays well under the message limit
  static constexpr std::size_t kMaxOverrides = 256;         // what a token carries, and so what a session may hold

  // What is wrong with `secret` (shorter than kMinSecretBytes), naming the fix; nullopt when nothing.
  static std::optional<std::string> secretProblem(const std::string& secret);
  // Fails where secretProblem() says.
  static Result<SignedResume> create(std::string secret, std::chrono::seconds lifetime, const scene::Scene& scene);

  // A token for `state`, its clock read at `now`; it expires `lifetime` after `wallNow`.
  std::string issue(const SessionState& state, Clock::time_point now, WallClock::time_point wallNow) const;

  // The state `token` carries, over `defaults` for anything it leaves out, its clock paused at the
  // token's scene time (playOnResume set when it was playing); or why it is refused: malformed, its
  // signature does not match (altered, or another secret's), issued for another scene, or expired.
  Result<SessionState> open(std::string_view token, const SessionSettings& defaults, Clock::time_point now,
                            WallClock::time_point wallNow) const;

 private:
  SignedResume(std::string secret, std::chrono::seconds lifetime, std::uint64_t fingerprint, std::size_t objects)
      : secret_(std::move(secret)), lifetime_(lifetime), fingerprint_(fingerprint), objects_(objects) {}
  std::string mac(std::string_view text) const;

  std::string secret_;
  std::chrono::seconds lifetime_;
  std::uint64_t fingerprint_;  // sceneFingerprint
  std::size_t objects_;
};

// The scene's name and object names hashed (FNV-1a, 64 bits): tokens name their scene by it.
std::uint64_t sceneFingerprint(const scene::Scene& scene);

}  // namespace specula::session
