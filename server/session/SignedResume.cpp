#include "session/SignedResume.h"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <cmath>

#include "CameraConversions.h"
#include "base/Base64Url.h"
#include "session/SettingsProtocol.h"
#include "specula.pb.h"

namespace specula::session {

namespace {

constexpr std::string_view kPrefix = "s1.";
constexpr std::size_t kMacBytes = 32;   // SHA-256
constexpr float kMaxCoordinate = 1e7f;  // as a camera message may hold
constexpr double kMaxSceneMs = 1e12;
constexpr float kMaxSpeed = 16.0f;

std::int64_t unixMilliseconds(WallClock::time_point time) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(time.time_since_epoch()).count();
}

bool finiteWithin(const glm::vec3& v, float bound) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
         glm::all(glm::lessThanEqual(glm::abs(v), glm::vec3(bound)));
}

}  // namespace

std::uint64_t sceneFingerprint(const scene::Scene& scene) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&](std::string_view text) {
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    hash = (hash ^ 0xffu) * 1099511628211ull;  // a separator no name holds, so "ab","c" differs from "a","bc"
  };
  add(scene.name);
  for (const scene::SceneObject& object : scene.objects) add(object.name);
  return hash;
}

std::optional<std::string> SignedResume::secretProblem(const std::string& secret) {
  if (secret.size() >= kMinSecretBytes) return std::nullopt;
  return "the resume secret has " + std::to_string(secret.size()) + " bytes; use at least " +
         std::to_string(kMinSecretBytes) +
         " random bytes, the same on every instance (e.g. head -c 48 /dev/urandom | base64 > resume.secret)";
}

Result<SignedResume> SignedResume::create(std::string secret, std::chrono::seconds lifetime,
                                          const scene::Scene& scene) {
  if (auto problem = secretProblem(secret)) return Error{*problem};
  return SignedResume(std::move(secret), lifetime, sceneFingerprint(scene), scene.objects.size());
}

std::string SignedResume::mac(std::string_view text) const {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret_.data(), static_cast<int>(secret_.size()),
       reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest, &length);
  return std::string(reinterpret_cast<const char*>(digest), length);
}

std::string SignedResume::issue(const SessionState& state, Clock::time_point now, WallClock::time_point wallNow) const {
  v1::ResumeState resume;
  resume.set_scene_fingerprint(fingerprint_);
  resume.set_issued_unix_ms(unixMilliseconds(wallNow));
  resume.set_expires_unix_ms(unixMilliseconds(wallNow + lifetime_));
  resume.set_width(static_cast<std::uint32_t>(state.width));
  resume.set_height(static_cast<std::uint32_t>(state.height));
  if (state.camera)
    *resume.mutable_camera() =
        protocol::cameraUpdate(state.camera->eye, state.camera->target, state.camera->up, state.camera->fovYDegrees);
  resume.set_scene_time_ms(state.clock.sceneMs(now));
  resume.set_playing(state.clock.playing() || state.playOnResume);
  resume.set_speed(state.clock.speed());
  std::size_t overrides = 0;
  for (const auto& [index, matrix] : state.overrides) {
    if (++overrides > kMaxOverrides) break;  // Session refuses more; never reached
    v1::ResumeOverride& out = *resume.add_overrides();
    out.set_object(index);
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row) out.add_object_to_world(matrix[column][row]);
  }
  *resume.mutable_settings() = settingsToProto(state.settings);
  const std::string signedText = std::string(kPrefix) + base64UrlEncode(resume.SerializeAsString());
  return signedText + "." + base64UrlEncode(mac(signedText));
}

Result<SessionState> SignedResume::open(std::string_view token, const SessionSettings& defaults, Clock::time_point now,
                                        WallClock::time_point wallNow) const {
  const std::string malformed = "resume token refused: it is not one this service issued (malformed)";
  if (token.size() > kMaxTokenBytes || !token.starts_with(kPrefix)) return Error{malformed};
  const std::size_t dot = token.rfind('.');
  if (dot <= kPrefix.size() - 1) return Error{malformed};
  const std::string_view signedText = token.substr(0, dot);
  const std::optional<std::string> signature = base64UrlDecode(token.substr(dot + 1));
  if (!signature || signature->size() != kMacBytes) return Error{malformed};
  const std::string expected = mac(signedText);
  if (CRYPTO_memcmp(expected.data(), signature->data(), kMacBytes) != 0)
    return Error{"resume token refused: its signature does not match (altered, or issued under another secret)"};
  const std::optional<std::string> payload = base64UrlDecode(signedText.substr(kPrefix.size()));
  v1::ResumeState resume;
  if (!payload || !resume.ParseFromString(*payload)) return Error{malformed};
  if (resume.scene_fingerprint() != fingerprint_) return Error{"resume token refused: it was issued for another scene"};
  if (unixMilliseconds(wallNow) > resume.expires_unix_ms())
    return Error{"resume token refused: it expired " +
                 std::to_string((unixMilliseconds(wallNow) - resume.expires_unix_ms()) / 1000) + " s ago"};

  // Signed by a holder of the secret, but checked as strictly as a client's messages all the same.
  SessionState state;
  state.settings = defaults;
  state.width = static_cast<int>(resume.width());
  state.height = static_cast<int>(resume.height());
  if (resume.has_camera()) {
    const v1::CameraUpdate& camera = resume.camera();
    math::Camera restored{protocol::toGlm(camera.eye()), protocol::toGlm(camera.target()), protocol::toGlm(camera.up()),
                          camera.fov_degrees()};
    if (!finiteWithin(restored.eye, kMaxCoordinate) || !finiteWithin(restored.target, kMaxCoordinate) ||
        math::cameraProblem(restored))
      return Error{"resume token refused: its camera is not a valid view"};
    state.camera = restored;
  }
  if (!std::isfinite(resume.scene_time_ms()) || std::abs(resume.scene_time_ms()) > kMaxSceneMs ||
      !std::isfinite(resume.speed()) || std::abs(resume.speed()) > kMaxSpeed)
    return Error{"resume token refused: its animation time or speed is out of range"};
  state.clock.setSpeed(resume.speed(), now);
  state.clock.seek(resume.scene_time_ms(), now);
  state.playOnResume = resume.playing();
  if (static_cast<std::size_t>(resume.overrides_size()) > kMaxOverrides)
    return Error{"resume token refused: too many overrides"};
  for (const v1::ResumeOverride& item : resume.overrides()) {
    if (item.object() >= objects_ || item.object_to_world_size() != 16)
      return Error{"resume token refused: a malformed object override"};
    glm::mat4 matrix;
    for (int i = 0; i < 16; ++i) {
      const float value = item.object_to_world(i);
      if (!std::isfinite(value)) return Error{"resume token refused: a malformed object override"};
      matrix[i / 4][i % 4] = value;
    }
    state.overrides[item.object()] = matrix;
  }
  if (Status settings = applySettingsUpdate(resume.settings(), state.settings); !settings)
    return Error{"resume token refused: " + settings.error()};
  return state;
}

}  // namespace specula::session
