#pragma once
// How specula.proto messages travel over WebSocket, chosen by subprotocol during the handshake. Header only,
// so the server's network layer negotiates it without linking protobuf.
#include <string_view>

namespace specula::protocol {

enum class Encoding {
  Proto,  // binary protobuf messages
  Json,   // proto3 JSON text messages
};

// The WebSocket subprotocol that asks for `encoding`.
constexpr std::string_view subprotocolName(Encoding encoding) {
  return encoding == Encoding::Proto ? "specula.v1.proto" : "specula.v1.json";
}

}  // namespace specula::protocol
