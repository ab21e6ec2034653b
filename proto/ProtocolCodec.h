#pragma once
// specula.proto on the wire: binary protobuf or proto3 JSON, as the connection's subprotocol says.
#include <string>
#include <string_view>

#include "WireEncoding.h"
#include "base/Result.h"
#include "specula.pb.h"

namespace specula::protocol {

// Decodes one client message. Fails (with a message naming the problem) on a message of the wrong
// WebSocket type for the encoding, undecodable or truncated bytes, unknown fields, or no kind set.
Result<v1::ClientMessage> decodeClientMessage(std::string_view payload, bool text, Encoding encoding);

std::string encodeServerMessage(const v1::ServerMessage& message, Encoding encoding);

// The inverse pair, for clients and tests.
std::string encodeClientMessage(const v1::ClientMessage& message, Encoding encoding);
Result<v1::ServerMessage> decodeServerMessage(std::string_view payload, Encoding encoding);

}  // namespace specula::protocol
