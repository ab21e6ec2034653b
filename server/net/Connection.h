#pragma once
// The seam between the network layer and the session layer. The network layer owns sockets,
// framing, deadlines and the outgoing queue; the session layer owns meaning. Neither sees the other's
// internals, so sessions are tested without sockets and the network without a renderer.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "WireEncoding.h"

namespace specula::net {

// WebSocket close codes the server uses (RFC 6455 §7.4.1).
enum class CloseCode : std::uint16_t {
  Normal = 1000,
  GoingAway = 1001,        // server shutting down
  BadPayload = 1007,       // undecodable, truncated or wrong-type message
  PolicyViolation = 1008,  // protocol misuse, e.g. a second hello or too many queued replies
  TooBig = 1009,           // message over the size limit
  TryAgainLater = 1013,    // --max-sessions reached
};

// What a session may do with its connection. Thread-safe: call from any thread. After the connection
// closed, calls are ignored.
class MessageSink {
 public:
  virtual ~MessageSink() = default;
  // Queued in order and never dropped (welcome, stats, errors). Too many unsent closes the connection.
  virtual void sendControl(std::string payload) = 0;
  // Latest wins: at most one frame is written at a time and one waits; a newer one replaces the
  // waiting one (ConnectionHandler::onFrameReplaced).
  virtual void sendFrame(std::string payload) = 0;
  // Sends what control messages are queued, then the close frame; drops a waiting frame.
  virtual void close(CloseCode code, std::string reason) = 0;
};

// The session side of one WebSocket connection. Calls come from the connection's strand, one at a time.
class ConnectionHandler {
 public:
  virtual ~ConnectionHandler() = default;
  virtual void onMessage(std::string_view payload, bool text) = 0;
  virtual void onOversizedMessage() = 0;  // the connection is being closed with 1009
  virtual void onWriteTimedOut() = 0;     // the client stopped reading: the connection is being dropped
  virtual void onFrameSent(std::size_t bytes) = 0;
  virtual void onFrameReplaced() = 0;
  virtual void onClosed() = 0;  // exactly once, when the connection is gone
};

struct UpgradeRequest {
  protocol::Encoding encoding = protocol::Encoding::Json;
};

// Turns accepted WebSocket connections into sessions.
class ConnectionAcceptor {
 public:
  virtual ~ConnectionAcceptor() = default;
  // Returns the handler for the new connection, or nullptr after refusing it through `sink`
  // (an error message and a close code).
  virtual std::shared_ptr<ConnectionHandler> accept(const UpgradeRequest& request,
                                                    std::shared_ptr<MessageSink> sink) = 0;
};

}  // namespace specula::net
