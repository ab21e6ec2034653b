// Client and server messages in both wire encodings (binary protobuf and proto3 JSON), as
// Session::onMessage and the clients decode them, and a decoded settings update applied as a session applies it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ProtocolCodec.h"
#include "session/SettingsProtocol.h"

using specula::protocol::Encoding;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view payload(reinterpret_cast<const char*>(data), size);
  for (const Encoding encoding : {Encoding::Proto, Encoding::Json}) {
    const auto message = specula::protocol::decodeClientMessage(payload, encoding == Encoding::Json, encoding);
    if (message && message->has_settings()) {
      specula::session::SessionSettings settings;
      (void)specula::session::applySettingsUpdate(message->settings(), settings);
    }
    (void)specula::protocol::decodeServerMessage(payload, encoding);
  }
  return 0;
}
