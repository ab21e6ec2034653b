#pragma once
// A blocking Specula WebSocket client for tools and tests: connect, send ClientMessages, receive
// ServerMessages with a timeout. One client per thread; Beast stays behind this header.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "ProtocolCodec.h"
#include "WireEncoding.h"
#include "base/Result.h"

namespace specula::client {

struct ServerAddress {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8080;
  std::string token;  // sent as ?token= when set
};

// "ws://host:port[/ws][?token=T]" (or http://, or host:port) → address; the error says what is expected.
Result<ServerAddress> parseServerUrl(const std::string& url);

struct CloseInfo {
  int code = 0;  // WebSocket close code the server sent; 0 when the connection just dropped
  std::string reason;
};

class SpeculaClient {
 public:
  // TCP connect and WebSocket upgrade on /ws with the encoding's subprotocol. Errors name the
  // address and what went wrong (refused, timed out, HTTP status of a declined upgrade).
  // receiveBufferBytes > 0 fixes the socket's receive buffer (and so the window the server may fill):
  // a thin pipe whose reader stops fills it within a frame, as a phone's would.
  static Result<std::unique_ptr<SpeculaClient>> connect(const ServerAddress& address, protocol::Encoding encoding,
                                                        std::chrono::milliseconds timeout = std::chrono::seconds(5),
                                                        int receiveBufferBytes = 0);
  ~SpeculaClient();

  Status send(const v1::ClientMessage& message);
  // Raw bytes as one WebSocket message (tests send garbage with it).
  Status sendRaw(const std::string& payload, bool text);
  // The next server message. Fails on timeout (the read stays pending for the next call), on a close
  // (closeInfo() then says why) and on an undecodable message.
  Result<v1::ServerMessage> receive(std::chrono::milliseconds timeout);
  std::optional<CloseInfo> closeInfo() const;
  // Normal close handshake (1000); safe to call twice.
  void close();
  // Closes the socket with no close handshake and unread data left, as a crashed client or a lost
  // network does (the server sees a reset, perhaps mid-frame).
  void abort();

 private:
  struct State;
  explicit SpeculaClient(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// Milliseconds on a steady clock, for CameraUpdate.client_time_ms and latency.
double steadyMilliseconds();

}  // namespace specula::client
