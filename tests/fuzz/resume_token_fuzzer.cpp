// Signed resume tokens as a hello carries them to SignedResume::open: the input as a token, and the input
// as a token's payload (v1::ResumeState bytes) signed under the service's secret, so the fuzzer gets past
// the signature to the state a token may carry.
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/Base64Url.h"
#include "session/SignedResume.h"

namespace {

using specula::session::SignedResume;

const std::string kSecret(SignedResume::kMinSecretBytes, 's');

// The scene tokens are issued for: its fingerprint (seeds carry it) and its object count bound overrides.
specula::scene::Scene fuzzScene() {
  specula::scene::Scene scene;
  scene.name = "fuzz";
  scene.objects.resize(2);
  scene.objects[0].name = "floor";
  scene.objects[1].name = "mirror";
  return scene;
}

// "s1." + base64url(payload) + "." + base64url(HMAC-SHA256 of what precedes the last dot), as issue() signs.
std::string signedToken(std::string_view payload) {
  const std::string text = "s1." + specula::base64UrlEncode(payload);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  HMAC(EVP_sha256(), kSecret.data(), static_cast<int>(kSecret.size()),
       reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest, &length);
  return text + "." + specula::base64UrlEncode(std::string_view(reinterpret_cast<const char*>(digest), length));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const SignedResume resume = SignedResume::create(kSecret, std::chrono::hours(1), fuzzScene()).value();
  // 2026-01-01: seeds expire in 2100, so they open.
  const specula::session::WallClock::time_point wallNow{std::chrono::seconds(1767225600)};
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (specula::base64UrlDecode(specula::base64UrlEncode(bytes)) != bytes) std::abort();
  const specula::session::SessionSettings defaults;
  (void)resume.open(bytes, defaults, specula::session::Clock::time_point{}, wallNow);
  (void)resume.open(signedToken(bytes), defaults, specula::session::Clock::time_point{}, wallNow);
  return 0;
}
